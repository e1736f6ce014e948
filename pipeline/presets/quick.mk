# Preset `quick` (the default): an ensemble of four seeds at 3000 nodes, five cycles, the
# resolution at which the protocol's one constant, the yield radius, was calibrated and its
# predictions tested (docs/SCIENCE.md). Measured error, the protocol's ladder at Δ̃ = 0.27
# (docs/studies/convergence_flat_unfold/, 3000 and 6000 nodes, seeds 1-3): seed by seed, P at
# 6000 nodes is 0.96-1.00 (± 3-4 %) of P here in cycles 3-5, 1.09 ± 0.11 in cycle 2 and
# 1.19 ± 0.09 in cycle 1; the creased length ℓ is 8-17 % higher at 6000 nodes in every cycle and
# the facet count 24-78 %. So P per cycle is within 15 % of the next rung except in cycle 1, and
# within 5 % from cycle 3; but from 6000 to 12000 nodes P falls by 8-19 % (three seeds, more
# with each cycle) while ℓ holds within 2-4 %, so no converged value of P is shown and this rung
# is not shown within 15 % of one; the facet statistics are the mesh's (docs/SCIENCE.md). Run
# time: 479-521 s of
# integration wall per seed (two at a time), about 20 minutes for the four seeds on 2 cores
# once built.
PRESET_SEEDS := 1 2 3 4
PRESET_THREADS := 1
PRESET_SETS := --set mesh.nodes=3000 --set protocol.cycles=5
