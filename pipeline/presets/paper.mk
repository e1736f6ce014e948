# Preset `paper`: the paper's resolution (Fig. 9) and five cycles; hours per seed (projected
# from the convergence ladder: about 2.5 h of one core per 5-cycle run). Not shown converged:
# P still grows about 30 % per doubling of the nodes at 6000 (docs/studies/convergence/), so
# the 5 % rule of a paper preset is not met by any resolution measured. The yield is
# the protocol's yield radius (c0 = 0.105 at 12000 nodes; docs/MODEL.md §7.5).
PRESET_SEEDS := 1 2 3
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=12000 --set protocol.cycles=5
