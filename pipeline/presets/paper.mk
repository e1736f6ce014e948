# Preset `paper`: the paper's resolution (Fig. 9) and five cycles; hours per seed.
PRESET_SEEDS := 1 2 3
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=12000 --set protocol.cycles=5 --set integrator.plastic_c0=0.1
