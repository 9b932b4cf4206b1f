# The thesis's study (Chapters 4 and 5) as a campaign of files, one target per unit of work:
#
#   mesh/cell_<V>.off                      rndmesh icosa            a mesh of V vertices
#   jam/N<N>_s<S>.xyz                      shellpack jam            a jammed packing per (N, seed)
#   compress/N<N>_s<S>/compress.csv        shellpack compress       the compression, with pack_<phi>.off
#   analyze/N<N>_s<S>.csv                  shellpack analyze        Chapter 4's structure of every pack
#   perc/N<N>_s<S>/d<delta>/<phi>.csv      percolate                one row (and the cluster at FLOW_DELTA)
#   flow/N<N>_s<S>/M<M>/<phi>.csv          lbflow                   one row per percolating cluster
#   tables/*.csv, fits/*.csv, report.html  study_tables.py, kcfit, study_report.py
#
# Run it through the top Makefile (make study, make study-report, make study-jobs). Every recipe
# is a plain call of the toolkit's programs behind $(RUN) (empty here, `srun ...` on Slurm);
# the programs write atomically, so a killed campaign leaves no half file and `make` picks up
# where it stopped; a compression killed half-way resumes from its checkpoint. The flow stage's
# targets depend on which clusters percolate, so the campaign runs in three passes
# (structure, flow, report), each a sub-make that reads the results of the one before.

STUDY ?= default
include scripts/study/presets/$(STUDY).mk

OUT       ?= out
STUDY_DIR ?= $(OUT)/study$(if $(filter default,$(STUDY)),,-$(STUDY))
BUILD     ?= build
THREADS   ?= 0
RUN       ?=
PYTHON    ?= /usr/bin/python3
D := $(STUDY_DIR)
BIN := $(D)/bin
TIMED := $(BIN)/timed.sh $(D)/log

range = $(shell scripts/study/range.sh '$(1)')
N_LIST      := $(strip $(N))
SEED_LIST   := $(call range,$(SEEDS))
PHI_LIST    := $(call range,$(PHI))
DELTA_LIST  := $(call range,$(DELTA))
REFINE_LIST := $(call range,$(REFINE))
FLOW_N_LIST := $(strip $(FLOW_N))
FLOW_SEED_LIST := $(call range,$(FLOW_SEEDS))

# Every campaign variable is checked before any work: one line each, then stop.
CHECK := $(shell scripts/study/check_variables.sh 'N=$(N)' 'SEEDS=$(SEEDS)' 'VERTICES=$(VERTICES)' \
  'PHI=$(PHI)' 'DELTA=$(DELTA)' 'FLOW_DELTA=$(FLOW_DELTA)' 'REFINE=$(REFINE)' 'FLOW_N=$(FLOW_N)' \
  'FLOW_SEEDS=$(FLOW_SEEDS)' 'THREADS=$(THREADS)' 1>&2; echo $$?)
ifneq ($(CHECK),0)
  $(error the campaign's variables above are out of range (STUDY=$(STUDY)); nothing was run)
endif

runs      := $(foreach n,$(N_LIST),$(foreach s,$(SEED_LIST),N$(n)_s$(s)))
flow_runs := $(foreach n,$(FLOW_N_LIST),$(foreach s,$(FLOW_SEED_LIST),N$(n)_s$(s)))
MESH      := $(D)/mesh/cell_$(VERTICES).off
JAMS      := $(foreach r,$(runs),$(D)/jam/$(r).xyz)
COMPRESSIONS := $(foreach r,$(runs),$(D)/compress/$(r)/compress.csv)
ANALYSES  := $(foreach r,$(runs),$(D)/analyze/$(r).csv)
PERC_ROWS := $(foreach r,$(runs),$(foreach d,$(DELTA_LIST),$(foreach p,$(PHI_LIST),$(D)/perc/$(r)/d$(d)/$(p).csv)))

# Parameters that no file name carries: a target that depends on them is remade when they change.
# (the stamp is rewritten only when its text changes, so an unchanged campaign stays made)
define stamp
$(shell mkdir -p $(D)/params; f=$(D)/params/$(1).txt; printf '%s\n' $(2) > $$f.new; \
  if cmp -s $$f.new $$f; then rm $$f.new; else mv $$f.new $$f; fi)
endef
# make study-status only reads: asked with other variables than the campaign's, a stamp it wrote
# would mark the campaign's finished targets out of date.
ifeq ($(MAKECMDGOALS),status)
  stamp :=
endif
$(call stamp,compress,'VERTICES=$(VERTICES)' 'COMPRESS_OPTS=$(COMPRESS_OPTS)' 'PHI=$(PHI_LIST)')
$(call stamp,percolate,'PERCOLATE_OPTS=$(PERCOLATE_OPTS)' 'FLOW_DELTA=$(FLOW_DELTA)')
$(call stamp,flow,'LBFLOW_OPTS=$(LBFLOW_OPTS)')
$(call stamp,jam,'JAM_OPTS=$(JAM_OPTS)')

.DELETE_ON_ERROR:
.SECONDARY:
.SECONDEXPANSION:
.PHONY: all structure flow report docs jobs tools scripts status

all:
	@scripts/study/check_tools.sh '$(RUN)'
	@$(MAKE) -f scripts/study/study.mk --no-print-directory structure
	@$(MAKE) -f scripts/study/study.mk --no-print-directory flow
	@$(MAKE) -f scripts/study/study.mk --no-print-directory $(D)/report.html

# The campaign runs the programs and recipe scripts it copied into $(BIN) at its start, so that
# one campaign is one version of the tools even when the checkout is rebuilt or edited while it
# runs (a shell reads a script as it goes: editing a running one breaks it). Delete $(BIN) to renew.
TOOLS := rndmesh shellpack percolate lbflow kcfit
RECIPE_SCRIPTS := timed.sh compress.sh flow.sh forward_signals.sh
$(BIN)/%.sh: | scripts/study/%.sh
	@mkdir -p $(BIN)
	cp scripts/study/$*.sh $@
$(BIN)/%: | $(BUILD)/bin/%
	@mkdir -p $(BIN)
	cp $(BUILD)/bin/$* $@
$(BUILD)/bin/%:
	@echo "study: $@ is missing: build the programs first (make study-tools)" >&2; exit 2
scripts: $(addprefix $(BIN)/,$(RECIPE_SCRIPTS))
tools: $(addprefix $(BIN)/,$(TOOLS))

structure: $(ANALYSES) $(PERC_ROWS)

$(MESH): | $(BIN)/rndmesh scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) mesh $@ $(BIN)/rndmesh icosa --level $(icosa_level) --radius 0.5 -q -o $@

# icosahedron quadrisected: level 1 has 12 vertices, each level about four times more
icosa_level = $(or $(word 2,$(subst :, ,$(filter $(VERTICES):%,12:1 42:2 162:3 642:4 2562:5 10242:6))),1)

$(D)/jam/%.xyz: $(D)/params/jam.txt | $(BIN)/shellpack scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) jam $@ $(BIN)/shellpack jam -N $(call n_of,$*) --seed $(call seed_of,$*) $(JAM_OPTS) \
	  -q -o $@ --csv /dev/null

n_of    = $(patsubst N%,%,$(word 1,$(subst _, ,$(1))))
seed_of = $(patsubst s%,%,$(word 2,$(subst _, ,$(1))))

# One compression per (N, seed); pack_<phi>.off at every target. With a checkpoint left by a
# killed run it resumes (the checkpoint repeats the run's arguments).
$(D)/compress/%/compress.csv: $(D)/jam/%.xyz $(MESH) $(D)/params/compress.txt | $(BIN)/shellpack scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) compress $@ $(BIN)/compress.sh $(BIN)/shellpack $(@D) $< $(MESH) '$(PHI_LIST)' \
	  $(THREADS) $(D)/params/compress.txt $(COMPRESS_OPTS)


$(D)/analyze/%.csv: $(D)/compress/%/compress.csv | $(BIN)/shellpack scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) analyze $@ $(BIN)/shellpack analyze $(foreach p,$(PHI_LIST),$(D)/compress/$*/pack_$(p).off) \
	  --threads $(THREADS) -q -o $@

# One percolate row per (packing, delta); the cluster image is kept at FLOW_DELTA only.
# (a packing is finished when its compression's table is: the table is written last)
$(D)/perc/%.csv: $$(D)/compress/$$(call run_of,$$*)/compress.csv $(D)/params/percolate.txt | $(BIN)/percolate scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) percolate $@ $(BIN)/percolate $(<D)/pack_$(notdir $*).off --delta $(call delta_of,$*) $(PERCOLATE_OPTS) --threads $(THREADS) -q \
	  --csv $@ $(if $(filter $(call delta_of,$*),$(FLOW_DELTA)),-o $(@:.csv=.vtk))

run_of   = $(word 1,$(subst /, ,$(1)))
delta_of = $(patsubst d%,%,$(word 2,$(subst /, ,$(1))))

# The second pass: one lbflow row per percolating cluster at FLOW_DELTA, for FLOW_N and FLOW_SEEDS.
ifneq ($(filter flow stage-flow status $(D)/report.html,$(MAKECMDGOALS)),)
FLOW_ROWS := $(foreach r,$(flow_runs),$(foreach m,$(REFINE_LIST),$(foreach p,$(shell scripts/study/percolating.sh \
  $(D)/perc/$(r)/d$(FLOW_DELTA) $(PHI_LIST)),$(D)/flow/$(r)/M$(m)/$(p).csv)))
endif
flow: $(FLOW_ROWS)

$(D)/flow/%.csv: $$(D)/perc/$$(call run_of,$$*)/d$(FLOW_DELTA)/$$(notdir $$*).vtk $(D)/params/flow.txt | $(BIN)/lbflow scripts
	@mkdir -p $(@D)
	$(RUN) $(TIMED) flow $@ $(BIN)/flow.sh $(BIN)/lbflow $< $(patsubst M%,%,$(word 2,$(subst /, ,$*))) $@ \
	  $(THREADS) $(D)/params/flow.txt $(LBFLOW_OPTS)

$(D)/perc/%.vtk: $(D)/perc/%.csv ; @test -f $@

# The third pass: tables (one per stage, rows of every finished target), fits and the report.
# `make study` remakes report.html when a result, a parameter or a report script is newer, so a
# finished campaign run again does nothing; `make study-report` (report) always writes it anew.
REPORT_PARAMS := 'N=$(N)' 'SEEDS=$(SEEDS)' 'VERTICES=$(VERTICES)' 'PHI=$(PHI)' 'DELTA=$(DELTA)' \
  'FLOW_DELTA=$(FLOW_DELTA)' 'REFINE=$(REFINE)' 'FLOW_N=$(FLOW_N)' 'FLOW_SEEDS=$(FLOW_SEEDS)' \
  'COMPRESS_OPTS=$(COMPRESS_OPTS)' 'PERCOLATE_OPTS=$(PERCOLATE_OPTS)' 'LBFLOW_OPTS=$(LBFLOW_OPTS)'
$(call stamp,report,$(REPORT_PARAMS))
define write_report
@scripts/study/check_tools.sh
$(PYTHON) scripts/study/study_report.py --dir $(D) --study $(STUDY) --bin $(BIN) --params $(REPORT_PARAMS)
endef
report: | $(BIN)/kcfit
	$(write_report)
$(D)/report.html: $(ANALYSES) $(PERC_ROWS) $(FLOW_ROWS) $(D)/params/report.txt $(wildcard scripts/study/*.py) | $(BIN)/kcfit
	$(write_report)

# The finished report, its numbers beside the thesis's and its figures copied into the
# documentation, the files a commit keeps (make study-docs): docs/study for the default
# campaign, docs/study-<STUDY> for another preset.
DOCS_DIR ?= docs/study$(if $(filter default,$(STUDY)),,-$(STUDY))
docs:
	@test -f $(D)/report.html || { echo "study: no report in $(D): run make study first" >&2; exit 2; }
	@rm -rf $(DOCS_DIR) && mkdir -p $(DOCS_DIR)/figures
	cp $(D)/report.html $(D)/summary.md $(DOCS_DIR)/
	cp $(D)/figures/*.png $(DOCS_DIR)/figures/

# How far the campaign is (make study-status): per stage, its finished targets of all, the
# seconds they took, their mean and the time left (stage_status.sh: the targets still to do
# counted per N, and per M for the flow), as CSV. The flow's targets are known only as far as
# percolate has run; a line on standard error says so while it has not.
status_targets_mesh      = $(MESH)
status_targets_jam       = $(JAMS)
status_targets_compress  = $(COMPRESSIONS)
status_targets_analyze   = $(ANALYSES)
status_targets_percolate = $(PERC_ROWS)
status_targets_flow      = $(FLOW_ROWS)
to_do     = $(filter-out $(wildcard $(1)),$(1))
with_text = $(foreach t,$(1),$(if $(findstring $(2),$(t)),$(t)))
# N,M:COUNT of the targets still to do
status_left_mesh = 0,0:$(words $(call to_do,$(MESH)))
status_left = $(foreach n,$(N_LIST),$(n),0:$(words $(call with_text,$(call to_do,$(status_targets_$(1))),/N$(n)_s)))
status_left_flow = $(foreach n,$(FLOW_N_LIST),$(foreach m,$(REFINE_LIST),$(n),$(m):$(words \
  $(call with_text,$(call with_text,$(call to_do,$(FLOW_ROWS)),/N$(n)_s),/M$(m)/))))
status:
	@echo "stage,done,total,seconds,mean_seconds,seconds_left"
	@$(foreach s,mesh jam compress analyze percolate flow,scripts/study/stage_status.sh $(s) \
	  $(words $(wildcard $(status_targets_$(s)))) $(words $(status_targets_$(s))) $(D)/log/$(s).csv \
	  $(or $(status_left_$(s)),$(call status_left,$(s)));)
	@$(if $(filter-out $(words $(PERC_ROWS)),$(words $(wildcard $(PERC_ROWS)))),echo "study: flow: \
	  the total counts the clusters found by the $(words $(wildcard $(PERC_ROWS))) of $(words $(PERC_ROWS)) \
	  percolate rows made so far" >&2)

# One stage's commands, one a line, for GNU parallel or a job array (make study-jobs STAGE=...):
# the recipes of the stage's unfinished targets, printed instead of run. A stage's jobs need the
# stage before it finished (jam, then compress, then analyze and percolate, then flow).
STAGE ?= compress
STAGES := jam compress analyze percolate flow
stage_before_compress := jam
stage_before_analyze := compress
stage_before_percolate := compress
stage_before_flow := percolate
.PHONY: $(addprefix stage-,$(STAGES))
stage-jam: $(MESH) $(JAMS)
stage-compress: $(COMPRESSIONS)
stage-analyze: $(ANALYSES)
stage-percolate: $(PERC_ROWS)
stage-flow: $(FLOW_ROWS)
jobs:
	@$(if $(filter $(STAGE),$(STAGES)),,echo "study: STAGE=$(STAGE): the stages are $(STAGES)" >&2; exit 2)
	@$(if $(stage_before_$(STAGE)),$(MAKE) -f scripts/study/study.mk -q stage-$(stage_before_$(STAGE)) || \
	  { echo "study: STAGE=$(STAGE) needs stage $(stage_before_$(STAGE)) finished first" >&2; exit 2; })
	@$(MAKE) -f scripts/study/study.mk --no-print-directory -s RUN=scripts/study/print_command.sh stage-$(STAGE)
