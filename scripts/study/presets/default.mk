# STUDY=default (make study): the largest campaign that finishes in about an hour on 2 cores
# with every figure of the report fed: 16 shells of 642 vertices (the coarsest mesh whose face
# barrier holds to phi = 0.95; one compression to 0.95 took 20 min on one core of a loaded
# machine), 6 seeds, phi from 0.60 to 0.95 in steps of 0.025, the thesis's five voxel sizes,
# and the flow at delta = 0.04 for M = 1 and 2 on 3 seeds. Run it with -j2.
N          ?= 16
SEEDS      ?= 1:6
VERTICES   ?= 642
PHI        ?= 0.60:0.95:0.025
DELTA      ?= 0.03:0.07:0.01
FLOW_DELTA ?= 0.04
REFINE     ?= 1,2
FLOW_N     ?= $(N)
FLOW_SEEDS ?= 1:3
COMPRESS_OPTS ?=
