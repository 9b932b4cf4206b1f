# STUDY=demo: make run's campaign, the whole chain in about a minute on 2 cores: 12 shells of 162
# vertices, 4 seeds, phi from 0.60 to 0.80, three voxel sizes, M = 1 at delta = 0.05.
N          ?= 12
SEEDS      ?= 1:4
VERTICES   ?= 162
PHI        ?= 0.60:0.80:0.05
DELTA      ?= 0.05,0.07,0.09
FLOW_DELTA ?= 0.05
REFINE     ?= 1
FLOW_N     ?= $(N)
FLOW_SEEDS ?= $(SEEDS)
COMPRESS_OPTS ?= --ftol 1e-4
