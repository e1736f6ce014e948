# Preset `quick` (the default): an ensemble of small sheets, about 13 minutes on 2 cores with the
# build (measured: each seed 6-6.5 min on one thread, two seeds at a time; 73-79 s per cycle).
PRESET_SEEDS := 1 2 3 4
PRESET_SETS := --set mesh.nodes=1500 --set protocol.cycles=5
