# Preset `quick` (the default): an ensemble of small sheets, about 20 minutes on 2 cores.
PRESET_SEEDS := 1 2 3
PRESET_SETS := --set mesh.nodes=1000 --set protocol.cycles=5
