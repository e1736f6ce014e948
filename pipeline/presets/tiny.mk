# Preset `tiny`: for CI, a few minutes end to end. Too coarse for physics; checks the plumbing.
PRESET_SEEDS := 1 2
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=300 --set protocol.cycles=2
