# STUDY=thesis: the thesis's sizes (Chapter 5, 5.2.1-5.2.3): N = 16, 32 and 50 shells of 2,562
# vertices (~5,000 triangles), t/D0 = 0.02, P0/E = 0.0025, constant volume, SVK membrane (the
# compress defaults); phi from 0.60 to 0.95 (porosity 0.40 to 0.05, past the threshold near
# 0.14); delta = 0.03-0.07 D0; the flow at delta = 0.04 for M = 1, 2, 3 on N = 50. The thesis
# averaged 50 simulations per N (Ch. 4) and does not say how many packings fed each
# percolation probability: 20 seeds per N here, the flow on the first 5 seeds of N = 50. A
# compression of 50 x 2,562 shells to phi 0.95 takes about 23 minutes on 2 cores with the options
# below (docs/study.md): hours here, minutes per task on a cluster (RUN='srun ...'). FIRE stops at
# --ftol 1e-4, three times fewer iterations than compress's default 1e-5, and the box side
# shrinks by up to 0.008 D0 a step instead of 0.004, 1.5 times fewer again; each moves the
# structure and the flow of a packing by much less than they differ between seeds
# (docs/study.md, "The FIRE tolerance, with eight seeds" and "The compression at the thesis's
# size in under 30 minutes").
N          ?= 16 32 50
SEEDS      ?= 1:20
VERTICES   ?= 2562
PHI        ?= 0.60:0.95:0.025
DELTA      ?= 0.03:0.07:0.01
FLOW_DELTA ?= 0.04
REFINE     ?= 1,2,3
FLOW_N     ?= 50
FLOW_SEEDS ?= 1:5
COMPRESS_OPTS ?= --ftol 1e-4 --step 0.008
# Near the threshold the flow settles slowly: at porosity 0.175 lbflow needed up to 448,200
# steps at M = 1 to reach --tol 1e-6 (N = 50, three seeds), past its default cap of 200,000, and
# the steps grow with M. The cap is raised so that those targets finish instead of failing.
LBFLOW_OPTS ?= --max-steps 2000000
