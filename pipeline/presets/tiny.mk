# Preset `tiny`: for CI, a few minutes end to end. Too coarse for physics; checks the plumbing.
# At 300 nodes a hinge must fold about 90 degrees to reach the protocol's 3.55 mm yield radius,
# so its runs leave few or no creases.
PRESET_SEEDS := 1 2
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=300 --set protocol.cycles=2
