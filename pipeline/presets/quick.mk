# Preset `quick` (the default): an ensemble of small sheets, about half an hour on 2 cores.
PRESET_SEEDS := 1 2 3 4
PRESET_SETS := --set mesh.nodes=1500 --set protocol.cycles=5
