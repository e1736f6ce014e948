# Preset `paper`: the paper's resolution (Fig. 9) and five cycles; hours per seed. The yield is
# the protocol's yield radius (c0 = 0.105 at 12000 nodes; docs/MODEL.md §7.5).
PRESET_SEEDS := 1 2 3
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=12000 --set protocol.cycles=5
