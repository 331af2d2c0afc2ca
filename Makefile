# The ray tracing lab kit.  `make help` lists the targets.
# Needs only a C11 compiler, make and a POSIX shell.

# ---- settings ---------------------------------------------------------------
CC        ?= cc
OPT       ?= -O2
STD        = -std=c11
WARN       = -Wall
WARN      += -Wextra
WARN      += -Wpedantic
WARN      += -Wshadow
WARN      += -Wstrict-prototypes
FPFLAGS    = -ffp-contract=off          # never contract a*b+c; never -ffast-math
CFLAGS     = $(STD) $(OPT) $(FPFLAGS) $(WARN)
SANFLAGS   = $(STD) -O1 -g $(FPFLAGS) $(WARN) -fsanitize=address,undefined \
             -fno-omit-frame-pointer -fno-sanitize-recover=all
# Linking a sanitized program.  gcc links UBSan's runtime as a shared
# library with 6 MB of zeroed globals, which LeakSanitizer reads through at
# every exit: about 1,550 page faults and 20 ms a process, more than the
# rest of a small test's run.  -static-libubsan links that runtime into the
# program, whose globals are small.  Only gcc knows the option (clang links
# its sanitizers' runtimes statically already): the recipe asks the
# compiler, once per sanitized link, not once per make.
SAN_LINK   = $(SANFLAGS) $$($(CC) -static-libubsan -E -x c /dev/null >/dev/null 2>&1 && echo -static-libubsan)
THREADS    = -pthread
RENDER_LTO = -flto                      # the renderer inlines across the stage files; empty to disable
LDLIBS     = -lm
SYSTEM    := $(shell uname -s)
# The archiver.  GNU ar loads every linker plugin installed beside it; where
# clang's LLVMgold is one, that loads all of LLVM (about 70 ms and 3,400
# page faults for the kit's dozen objects).  gcc-ar hands ar gcc's own
# plugin, and ar loads that one alone (about 10 ms); the archive is the
# same.  On Linux, where ar is GNU ar, gcc-ar is used if it is on PATH
# (found without starting a process); plain ar elsewhere.
KIT_AR    ?= $(if $(filter Linux,$(SYSTEM)),$(firstword $(wildcard $(addsuffix /gcc-ar,$(subst :, ,$(PATH)))) ar),ar)

# A copy of the kit with Windows line ends (CRLF), as Git for Windows checks
# files out where core.autocrlf is set and no .gitattributes says LF (the
# kit's does; a template made from an older kit may not): the shell cannot
# run its scripts, and the grader refuses its own test files.  Say so, and
# how to mend it without losing work, before anything else fails ($(empty)
# keeps the commands' indent, which make would strip).
empty :=
ifneq ($(shell grep -l "$$(printf '\r')" tests/run.sh 2>/dev/null),)
$(info this copy of the kit has Windows line ends (CRLF), which the shell cannot run:)
$(info Git for Windows wrote them when it checked the files out.  To mend the copy,)
$(info commit your work (git commit -am "my work"), then, in this folder:)
$(info $(empty)    git config core.autocrlf false)
$(info $(empty)    git rm -rq --cached . && git reset -q --hard)
$(info or clone the repository again from a WSL (Linux) terminal.)
$(error the kit's files have Windows line ends)
endif

# Quiet by default: the kit's own build commands are not echoed, and a
# stage file (the file a student edits) is named as make render compiles
# it.  V=1 echoes every command.  Warnings and errors print either way.
V         ?=
Q          = $(if $(filter 1,$(V)),,@)
SAY_CC     = $(if $(Q),@echo "  CC      $<")

# What the targets act on (all accept absolute paths).
SUBMISSION ?= labs
SCENE      ?= labs/scenes/default.scene
SIZE       ?=
PART       ?=
RESULTS    ?=
FORMAT     ?=
CLASSROOM  ?=
SUBMISSIONS ?=
JOBS       ?=
PREVIOUS   ?=

# Where the builds go: OUT_ROOT=dir builds into dir/build and dir/asan (the
# portability suite builds with a second compiler beside the first).
OUT_ROOT  ?= out
BUILD      = $(OUT_ROOT)/build
ASAN       = $(OUT_ROOT)/asan
STAGES     = part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color \
             part4_plane_intersect part5_triangle_intersect
HAVE_SOLUTIONS := $(wildcard solutions/part1_image_plane.c)

# ---- the framework students use (labs/kit) ---------------------------------
KIT_SRC    = labs/kit/image.c labs/kit/png.c labs/kit/zlib.c labs/kit/scene.c labs/kit/render.c \
             labs/kit/numtext.c labs/kit/savefile.c labs/kit/textfile.c labs/kit/obj.c \
             labs/kit/bvh.c labs/kit/closest.c labs/kit/compare.c labs/kit/edges.c
KIT_HDR    = $(wildcard labs/*.h labs/kit/*.h)
KIT_OBJ    = $(KIT_SRC:labs/kit/%.c=$(BUILD)/kit/%.o)
KIT_ASAN   = $(KIT_SRC:labs/kit/%.c=$(ASAN)/kit/%.o)

.PHONY: all help render compare grade grade-all gradescope student-kit bench \
        handouts test test-build unit-tests clean grader public-tests fuzz sanitize-grader \
        submission-dir sort-submissions
.DELETE_ON_ERROR:
.SECONDARY:                             # keep the objects a chain of rules makes (the renderer's lto/)
.SECONDEXPANSION:
# A target's directory is made once, before the first target in it (an
# order-only prerequisite "| $$(@D)/."), not by a mkdir per target.
%/.:
	@mkdir -p $@

all: $(BUILD)/kit/libkit.a $(BUILD)/bin/compare $(BUILD)/sub/labs/render \
     $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render) grader unit-tests

# The student kit (no solutions/) lists only what runs there.
help:
	@echo "make render  [SUBMISSION=dir] [SCENE=file] [SIZE=WxH] [OUT=file]"
	@echo "make compare [SUBMISSION=dir] [SCENE=file]"
	@echo "make grade   [SUBMISSION=dir] [PART=1|2|3a|3b|4|5] [FAILURES=all] [RESULTS=file]"
	@echo "             [FORMAT=gradescope|prairielearn] [CLASSROOM=file]"
ifneq ($(HAVE_SOLUTIONS),)
	@echo "make grade-all SUBMISSIONS=dir [OUT=dir] [JOBS=n] [PREVIOUS=dir]"
	@echo "make sort-submissions FROM=download.zip|dir TO=newdir [MAX_MB=n] [MAX_RATIO=n]"
	@echo "make gradescope | prairielearn | student-kit | bench | fuzz | sanitize-grader | handouts | test | clean"
else
	@echo "make test | clean"
endif
	@echo "V=1 after any of them echoes the build's compiler commands"

$(BUILD)/kit/%.o: labs/kit/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(THREADS) -c $< -o $@
$(ASAN)/kit/%.o: labs/kit/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) $(THREADS) -c $< -o $@
$(BUILD)/kit/libkit.a: $(KIT_OBJ)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^
$(ASAN)/kit/libkit.a: $(KIT_ASAN)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^

# ---- renderer and compare, per submission ----------------------------------
# A submission's build lives in out/build/sub/<name>: labs and solutions by
# name, any other directory by its absolute path with / turned into _.
# Stage files the submission lacks come from labs/ (the skeletons).  A
# folder with no stage file of its own but some in its labs/ (a repository
# made from the student kit) is rendered from there, as the grader grades it.
sub_name   = $(if $(filter labs solutions,$(1)),$(1),$(subst /,_,$(abspath $(1))))
stage_src  = $(firstword $(wildcard $(2)/$(1).c) labs/$(1).c)
stage_dir  = $(if $(wildcard $(STAGES:%=$(1)/%.c)),$(1),$(if $(wildcard $(STAGES:%=$(1)/labs/%.c)),$(1)/labs,$(1)))
SUB_DIR   := $(call stage_dir,$(SUBMISSION))
SUB_NAME  := $(call sub_name,$(SUB_DIR))
SUB_BUILD  = $(BUILD)/sub/$(SUB_NAME)

# The renderer's own objects (lto/) are built with link-time optimisation,
# so the per-pixel calls into the stage files can be inlined.
$(BUILD)/sub/labs/%.o: labs/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(BUILD)/sub/solutions/%.o: solutions/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
# A stage file the student edits: bin/stagecheck first refuses one the
# grader would not build (a header of the student's own: it compiles each
# stage file alone; tests/grader/own_headers.h).  One that does not compile:
# bin/lookalike then names what in it only looks like C (a non-breaking
# space, curly quotes...), as the grader does (tests/grader/lookalike.h).
STAGE_CC = $(BUILD)/bin/stagecheck $< && \
           { $(CC) $(CFLAGS) $(RENDER_LTO) -Ilabs -c $< -o $@ || { $(BUILD)/bin/lookalike $<; exit 1; }; }
STAGE_TOOLS = $(BUILD)/bin/stagecheck $(BUILD)/bin/lookalike
$(BUILD)/sub/labs/lto/%.o: labs/%.c $(KIT_HDR) | $$(@D)/. $(STAGE_TOOLS)
	$(SAY_CC)
	$(Q)$(STAGE_CC)
$(BUILD)/sub/solutions/lto/%.o: solutions/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) -Ilabs -c $< -o $@
ifeq ($(filter labs solutions,$(SUB_NAME)),)
$(SUB_BUILD)/lto/%.o: $$(call stage_src,$$*,$(SUB_DIR)) $(KIT_HDR) | $$(@D)/. $(STAGE_TOOLS)
	$(SAY_CC)
	$(Q)$(STAGE_CC)
endif
$(BUILD)/kit/lto/%.o: labs/kit/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) $(THREADS) -c $< -o $@
RENDER_OBJ = $(BUILD)/kit/lto/render_main.o $(BUILD)/kit/lto/render.o $(BUILD)/kit/lto/image.o \
             $(BUILD)/kit/lto/closest.o $(BUILD)/kit/lto/bvh.o
# A link that fails: bin/linkcheck then says what the linker's message
# means for the stage files (tests/grader/linkcheck_main.c): a helper
# defined in two of them, most often, which make render cannot link and the
# grader, building each alone, does not mind.
render_src = $(if $(filter labs solutions,$(1)),$(STAGES:%=$(1)/%.c),\
                 $(foreach s,$(STAGES),$(call stage_src,$(s),$(SUB_DIR))))
$(BUILD)/sub/%/render: $(RENDER_OBJ) \
                       $$(addprefix $(BUILD)/sub/$$*/lto/,$$(addsuffix .o,$$(STAGES))) $(BUILD)/kit/libkit.a \
                       | $(BUILD)/bin/linkcheck
	$(Q)$(CC) $(CFLAGS) $(RENDER_LTO) $(THREADS) $^ -o $@ $(LDLIBS) 2>$@.log || \
	    { cat $@.log >&2; $(BUILD)/bin/linkcheck $@.log $(call render_src,$*); rm -f $@.log; exit 1; }; \
	    cat $@.log >&2; rm -f $@.log
$(BUILD)/bin/compare: $(BUILD)/kit/compare_main.o $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)

SCENE_NAME = $(basename $(notdir $(SCENE)))
OUT_RENDER = $(if $(OUT),$(OUT),out/$(SCENE_NAME).png)

# SUBMISSION must be a folder: a mistyped one is refused, not drawn with the
# skeletons (the stage files a submission lacks) over out/default.png.
submission-dir:
	@test -d "$(SUBMISSION)" || { echo "make: SUBMISSION=$(SUBMISSION) is not a directory"; exit 2; }
	@test -n "$(wildcard $(STAGES:%=$(SUB_DIR)/%.c))" || \
	    echo "note: $(SUBMISSION) holds no stage file (nor does its labs folder): the skeletons are drawn"

# In the student kit, a note when labs/raytracer.h or labs/vec3.h is not as
# shipped (tests/grader/shipped): make render builds with the student's
# copy, the instructor's grader with the kit's own (as make grade does).
SHIPPED_HDR = $(wildcard tests/grader/shipped/raytracer.h tests/grader/shipped/vec3.h)
render: submission-dir $(SUB_BUILD)/render
	$(SUB_BUILD)/render "$(SCENE)" $(if $(SIZE),--size $(SIZE)) -o "$(OUT_RENDER)"
	@for h in $(notdir $(SHIPPED_HDR)); do cmp -s labs/$$h tests/grader/shipped/$$h || \
	    echo "note: labs/$$h is not the one the kit came with. make render used yours; your instructor grades your part*.c files with the kit's own (tests/grader/shipped/$$h), where what they use from your change will be missing: keep it in your part*.c files."; done

# In the kit's own repository the reference image is rendered with
# solutions/; in the student kit it is the stored render under labs/reference.
# Either way with its pixels on an edge (labs/kit/edges.h), where a colour
# that rounding decides is equal.
REF_IMAGE = $(if $(HAVE_SOLUTIONS),out/compare/$(SCENE_NAME)-reference.png,labs/reference/$(SCENE_NAME).png)
REF_EDGES = $(REF_IMAGE:.png=.edges)
compare: submission-dir $(SUB_BUILD)/render $(BUILD)/bin/compare $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render)
	@mkdir -p out/compare
	$(SUB_BUILD)/render "$(SCENE)" -o out/compare/$(SCENE_NAME)-submission.png
	$(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render "$(SCENE)" --quiet -o $(REF_IMAGE) --edges $(REF_EDGES))
	$(BUILD)/bin/compare out/compare/$(SCENE_NAME)-submission.png $(REF_IMAGE) \
	    --edges $(REF_EDGES) -o out/compare/$(SCENE_NAME).png

# ---- the oracle: independent double-double answers (tests/oracle) ----------
ORACLE_SRC = $(filter-out %_main.c,$(wildcard tests/oracle/*.c))
ORACLE_OBJ = $(ORACLE_SRC:tests/oracle/%.c=$(BUILD)/oracle/%.o)
$(BUILD)/oracle/%.o: tests/oracle/%.c $(wildcard tests/oracle/*.h) $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(ASAN)/oracle/%.o: tests/oracle/%.c $(wildcard tests/oracle/*.h) $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(BUILD)/oracle/liboracle.a: $(ORACLE_OBJ)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^
$(ASAN)/oracle/liboracle.a: $(ORACLE_SRC:tests/oracle/%.c=$(ASAN)/oracle/%.o)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^

# ---- instructor tools: archives (zip, tar.gz) and JSON (tests/tools) -------
TOOLS_SRC  = $(filter-out %_main.c,$(wildcard tests/tools/*.c))
TOOLS_OBJ  = $(TOOLS_SRC:tests/tools/%.c=$(BUILD)/tools/%.o)
$(BUILD)/tools/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(ASAN)/tools/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(BUILD)/tools/libtools.a: $(TOOLS_OBJ)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^
$(ASAN)/tools/libtools.a: $(TOOLS_SRC:tests/tools/%.c=$(ASAN)/tools/%.o)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^
$(BUILD)/bin/pack: $(BUILD)/tools/pack_main.o $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
# The report page's checker (tests/suites/report.sh).
$(BUILD)/bin/htmlcheck: $(BUILD)/tools/htmlcheck_main.o | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
all: $(BUILD)/bin/htmlcheck

# ---- the autograder (tests/grader) ------------------------------------------
# In the instructor's kit the grader also draws the hidden tests with the
# oracle (tests/oracle, tests/hidden); the student kit has neither.
HAVE_ORACLE := $(wildcard tests/oracle/oracle.h)
HAVE_HIDDEN := $(wildcard tests/hidden/hidden.c)
GRADER_LIB_SRC = tests/grader/cases.c tests/grader/check.c tests/grader/sandbox.c tests/grader/jail.c \
                 tests/grader/build.c tests/grader/memo.c tests/grader/include_scan.c tests/grader/linkmsg.c tests/grader/lookalike.c \
                 tests/grader/own_headers.c tests/grader/config.c tests/grader/grade.c \
                 tests/grader/report_table.c tests/grader/report_json.c \
                 tests/grader/diagnose.c tests/grader/lmsname.c tests/grader/terminal.c \
                 tests/grader/report_render.c tests/grader/report_html.c tests/grader/markup.c \
                 $(wildcard tests/grader/fig*.c)
GRADER_LIB_SRC += tests/grader/report_classroom.c tests/grader/report_prairielearn.c
# The class page of grade --all (report_class.h) and the CSV files' fields.
GRADER_LIB_SRC += tests/grader/report_class.c $(wildcard tests/grader/class_*.c) tests/grader/csv.c
GRADER_HDR = $(wildcard tests/grader/*.h) $(KIT_HDR)
GRADER_OBJ = $(GRADER_LIB_SRC:tests/grader/%.c=$(BUILD)/grader/%.o)
HARNESS    = $(BUILD)/grader/harness_1.o $(BUILD)/grader/harness_2.o \
             $(BUILD)/grader/harness_3.o $(BUILD)/grader/harness_4.o \
             $(BUILD)/grader/harness_5.o $(BUILD)/grader/harness_6.o \
             $(BUILD)/grader/harness_render.o
GRADER_REF = $(if $(HAVE_SOLUTIONS),$(STAGES:%=$(BUILD)/grader/ref_%.o))
GRADE_DEFS = $(if $(and $(HAVE_ORACLE),$(HAVE_HIDDEN)),-DGRADER_ORACLE)
GRADE_EXTRA = $(if $(GRADE_DEFS),$(BUILD)/grader/hidden.o $(BUILD)/oracle/liboracle.a)

$(BUILD)/grader/%.o: tests/grader/%.c $(GRADER_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(BUILD)/grader/harness_%.o: tests/grader/harness.c tests/grader/hexfloat.h tests/grader/harness_init.h \
                             $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -DHARNESS_PART=$* -c $< -o $@
# The report page's render program (build_render): harness_render.c draws a scene.
$(BUILD)/grader/harness_render.o: tests/grader/harness_render.c tests/grader/harness_init.h \
                                 $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(BUILD)/grader/ref_%.o: $(BUILD)/sub/solutions/%.o
	$(Q)cp $< $@
# On Linux each part's program is also prebuilt as a runner (harness_load.c):
# the grader then builds a student's file as a shared object, which costs a
# fraction of linking a whole program, and the runner loads it (build.c).
# runner_partP holds the harness for Part P and, in the instructor's kit,
# the reference for every other part; HARNESS_PART numbers the parts 1 to 6
# in PARTS' order.
PARTS      = 1 2 3a 3b 4 5
LOAD_RUNNERS := $(if $(filter Linux,$(SYSTEM)),1)
RUNNERS    = $(if $(LOAD_RUNNERS),$(foreach p,$(PARTS),$(BUILD)/grader/runner_part$(p)))
RUNNER_DEFS = $(if $(HAVE_SOLUTIONS),-DHARNESS_REFS)
$(BUILD)/grader/harness_load_%.o: tests/grader/harness.c tests/grader/harness_load.h \
                                  tests/grader/harness_init.h tests/grader/hexfloat.h \
                                  $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -DHARNESS_PART=$* -DHARNESS_LOAD $(RUNNER_DEFS) -c $< -o $@
$(BUILD)/grader/harness_load.o: tests/grader/harness_load.c tests/grader/harness_load.h \
                                tests/grader/contract.h $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
# (runner_part3a leaves out Part 3b's reference too: it calls
# sphere_intersect, which only the student's object defines.)
runner_refs = $(if $(HAVE_SOLUTIONS),$(filter-out $(BUILD)/grader/ref_$(word $(1),$(STAGES)).o \
              $(if $(filter 3,$(1)),$(BUILD)/grader/ref_part3b_ray_color.o),$(GRADER_REF)))
define RUNNER_RULE
$(BUILD)/grader/runner_part$(word $(1),$(PARTS)): $(BUILD)/grader/harness_load_$(1).o \
                           $(BUILD)/grader/harness_load.o $(call runner_refs,$(1))
	$(Q)$$(CC) $$(CFLAGS) -rdynamic $$^ -o $$@ $$(LDLIBS) -ldl
endef
$(foreach k,1 2 3 4 5 6,$(eval $(call RUNNER_RULE,$(k))))
$(BUILD)/grader/hidden.o: tests/hidden/hidden.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(BUILD)/grader/libgrader.a: $(GRADER_OBJ)
	$(Q)rm -f $@ && $(KIT_AR) rcs $@ $^
$(BUILD)/grader/grade_main.o: tests/grader/grade_main.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(GRADE_DEFS) -DGRADER_BUILD='"$(BUILD)"' -Ilabs -c $< -o $@
$(BUILD)/bin/grade: $(BUILD)/grader/grade_main.o $(GRADE_EXTRA) $(BUILD)/grader/libgrader.a \
                    $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a | $(HARNESS) $(GRADER_REF) $(RUNNERS) $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/lookalike: $(BUILD)/grader/lookalike_main.o $(BUILD)/grader/lookalike.o \
                        $(BUILD)/tools/utf8.o $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/linkcheck: $(BUILD)/grader/linkcheck_main.o $(BUILD)/grader/linkmsg.o \
                        $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/stagecheck: $(BUILD)/grader/stagecheck_main.o $(BUILD)/grader/include_scan.o \
                         $(BUILD)/grader/own_headers.o $(BUILD)/grader/lookalike.o \
                         $(BUILD)/tools/utf8.o $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/gentests: $(BUILD)/oracle/gentests_main.o $(BUILD)/oracle/liboracle.a \
                       $(BUILD)/grader/libgrader.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
# The reference solutions' accuracy on the hard cases (tables for the README).
$(BUILD)/bin/accuracy: $(BUILD)/oracle/accuracy_main.o $(BUILD)/oracle/liboracle.a \
                       $(STAGES:%=$(BUILD)/sub/solutions/%.o) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)

grader: $(BUILD)/bin/grade $(HARNESS) $(GRADER_REF) $(RUNNERS)

# The report page (out/report/index.html) shows the default scene drawn by
# the submission beside the reference's picture: in the instructor's kit
# rendered here with solutions/, in the student kit the stored
# labs/reference/default.png (the grader takes the first that exists).
REPORT_REF = $(if $(HAVE_SOLUTIONS),$(BUILD)/report/default.png)
$(BUILD)/report/default.png: $(BUILD)/sub/solutions/render labs/scenes/default.scene | $$(@D)/.
	$(Q)$(BUILD)/sub/solutions/render labs/scenes/default.scene --quiet -o $@
all: $(REPORT_REF)
grade: grader $(REPORT_REF)
	@$(BUILD)/bin/grade --submission "$(SUBMISSION)" $(if $(PART),--part $(PART)) \
	    $(if $(RESULTS),--results "$(RESULTS)") $(if $(FORMAT),--format "$(FORMAT)") \
	    $(if $(CLASSROOM),--classroom "$(CLASSROOM)") $(if $(filter all,$(FAILURES)),--all-failures) \
	    --report out/report

grade-all: grader $(REPORT_REF)
	@test -n "$(SUBMISSIONS)" || { echo "usage: make grade-all SUBMISSIONS=dir [OUT=dir] [PREVIOUS=dir]"; exit 2; }
	@$(BUILD)/bin/grade --all "$(SUBMISSIONS)" --out "$(if $(OUT),$(OUT),out/grades)" $(if $(JOBS),--jobs $(JOBS)) \
	    $(if $(PREVIOUS),--previous "$(PREVIOUS)")

# A class's download from Canvas, Moodle or Blackboard (one zip, or folder,
# of every student's files, each name carrying its student), sorted into
# one folder per submission for grade-all (tests/grader/sortsubs_main.c).
$(BUILD)/bin/sortsubs: $(BUILD)/grader/sortsubs_main.o $(BUILD)/grader/libgrader.a \
                       $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
grader: $(BUILD)/bin/sortsubs
sort-submissions: $(BUILD)/bin/sortsubs
	@test -n "$(FROM)" && test -n "$(TO)" || { echo "usage: make sort-submissions FROM=download.zip|dir TO=newdir [MAX_MB=n] [MAX_RATIO=n]"; exit 2; }
	@$(BUILD)/bin/sortsubs $(if $(MAX_MB),--max-mb "$(MAX_MB)") $(if $(MAX_RATIO),--max-ratio "$(MAX_RATIO)") "$(FROM)" "$(TO)"

# The public tests' expected values, from the oracle (commit the result).
public-tests: $(BUILD)/bin/gentests
	$(BUILD)/bin/gentests tests/public

# ---- releases: the Gradescope bundle and the student kit ------------------
SCENES     = $(wildcard labs/scenes/*.scene)

# autograder.zip: setup.sh and run_autograder at its root, beside the kit.
gradescope: $(BUILD)/bin/pack
	rm -rf out/gradescope/bundle && mkdir -p out/gradescope/bundle
	cp -R Makefile labs solutions tests out/gradescope/bundle/
	cp tests/gradescope/setup.sh tests/gradescope/run_autograder out/gradescope/bundle/
	$(BUILD)/bin/pack zip out/gradescope/autograder.zip out/gradescope/bundle
	@echo "wrote out/gradescope/autograder.zip"

# The PrairieLearn question: info.json, question.html, and tests/ with the
# grading entrypoint and the kit it builds (tests/prairielearn/question.sh).
.PHONY: prairielearn
prairielearn:
	sh tests/prairielearn/question.sh out/prairielearn/raytracer-lab

# The student kit: skeletons, framework, scenes and their reference renders,
# the grader with the public tests, the handouts.  No solutions/, no hidden
# tests, no oracle, and none of the instructor's test material (nor the
# hidden cases' seed from tests/weights.conf).
KIT_DIR    = out/student-kit
student-kit: $(BUILD)/bin/pack $(BUILD)/sub/solutions/render
	rm -rf $(KIT_DIR) && mkdir -p $(KIT_DIR)/tests/unit $(KIT_DIR)/labs/reference
	cp -R Makefile .gitattributes .gitignore labs handouts $(KIT_DIR)/
	mv $(KIT_DIR)/handouts/student-readme.md $(KIT_DIR)/README.md
	mkdir -p $(KIT_DIR)/.github/workflows
	sh tests/classroom/workflow.sh >$(KIT_DIR)/.github/workflows/classroom.yml
	cp -R tests/grader tests/public tests/tools tests/run.sh $(KIT_DIR)/tests/
	sed 's/^[ 	]*seed[ 	].*/# seed: the hidden cases'"'"' seed is the instructor'"'"'s (the student kit has no hidden tests)/' \
	    tests/weights.conf >$(KIT_DIR)/tests/weights.conf
	mkdir -p $(KIT_DIR)/tests/grader/shipped && cp labs/raytracer.h labs/vec3.h $(KIT_DIR)/tests/grader/shipped/
	cp tests/unit/check.h tests/unit/test_vec3.c tests/unit/test_png.c tests/unit/test_scene.c \
	   $(KIT_DIR)/tests/unit/
	for s in $(SCENES); do \
	    n=$(KIT_DIR)/labs/reference/$$(basename $$s .scene); \
	    $(BUILD)/sub/solutions/render $$s --quiet -o $$n.png --edges $$n.edges || exit 1; \
	done
	$(BUILD)/bin/pack targz out/student-kit.tar.gz $(KIT_DIR) student-kit
	@echo "wrote $(KIT_DIR)/ and out/student-kit.tar.gz"

# The compile flags, for the suites' small helper programs (tests/lib/cc_build.sh).
.PHONY: print-cflags
print-cflags:
	@echo $(CFLAGS)

# ---- handouts --------------------------------------------------------------
# The handouts' figures, drawn by the kit from the reference and from faulty
# variants (handouts/figures/make-figures.sh); commit the PNGs it writes.
# The student kit has no solutions/: its figures come ready-made.
handouts: $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render $(BUILD)/bin/compare grader)
ifneq ($(HAVE_SOLUTIONS),)
	MAKE="$(MAKE)" sh handouts/figures/make-figures.sh
else
	@echo "the figures are in handouts/figures (drawing them again needs solutions/)"
endif

# ---- unit tests of the framework (tests/unit) ------------------------------
UNIT_SRC   = $(wildcard tests/unit/test_*.c)
UNIT_BIN   = $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
UNIT_ASAN  = $(UNIT_SRC:tests/unit/%.c=$(ASAN)/tests/%)
REF_DIR    = $(if $(HAVE_SOLUTIONS),solutions,labs)
REF_OBJ    = $(STAGES:%=$(BUILD)/sub/$(REF_DIR)/%.o)
REF_ASAN   = $(STAGES:%=$(ASAN)/sub/$(REF_DIR)/%.o)
unit-tests: $(UNIT_BIN)
$(ASAN)/sub/solutions/%.o: solutions/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(ASAN)/sub/labs/%.o: labs/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
UNIT_LIBS  = $(if $(HAVE_ORACLE),$(BUILD)/oracle/liboracle.a) $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a
UNIT_LIBS_ASAN = $(UNIT_LIBS:$(BUILD)/%=$(ASAN)/%)
# (Not the grader's units: their own rules are below.)
GRADER_UNITS = sandbox include_scan memo cases check linkmsg lookalike own_headers lmsname terminal csv
UNIT_PLAIN = $(filter-out $(GRADER_UNITS:%=$(BUILD)/tests/test_%) \
                         $(BUILD)/tests/test_hidden $(BUILD)/tests/test_figures $(BUILD)/tests/test_bvh,\
                         $(UNIT_BIN))
$(UNIT_PLAIN): $(BUILD)/tests/%: tests/unit/%.c tests/unit/check.h $(REF_OBJ) $(UNIT_LIBS) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(THREADS) -Ilabs $< $(REF_OBJ) $(UNIT_LIBS) -o $@ $(LDLIBS)
$(ASAN)/tests/%: tests/unit/%.c tests/unit/check.h $(REF_ASAN) $(UNIT_LIBS_ASAN) | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $(THREADS) -Ilabs $< $(REF_ASAN) $(UNIT_LIBS_ASAN) -o $@ $(LDLIBS)

# test_bvh links its own sphere_intersect and triangle_intersect, which
# pass each call on to the reference's (compiled under other names) or to
# deliberately wrong ones; the other parts are the reference's.
BVH_RENAME = -Dsphere_intersect=reference_sphere_intersect -Dtriangle_intersect=reference_triangle_intersect
BVH_OWN    = part3a_sphere_intersect part5_triangle_intersect
BVH_REF    = $(BVH_OWN:%=$(BUILD)/tests/obj/renamed_%.o) \
             $(filter-out $(BVH_OWN:%=$(BUILD)/sub/$(REF_DIR)/%.o),$(REF_OBJ))
BVH_REF_ASAN = $(BVH_OWN:%=$(ASAN)/tests/obj/renamed_%.o) \
               $(filter-out $(BVH_OWN:%=$(ASAN)/sub/$(REF_DIR)/%.o),$(REF_ASAN))
$(BUILD)/tests/obj/renamed_%.o: $(REF_DIR)/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(BVH_RENAME) -Ilabs -c $< -o $@
$(ASAN)/tests/obj/renamed_%.o: $(REF_DIR)/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) $(BVH_RENAME) -Ilabs -c $< -o $@
$(BUILD)/tests/obj/test_bvh.o: tests/unit/test_bvh.c tests/unit/check.h $(KIT_HDR) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(THREADS) -Ilabs -c $< -o $@
$(BUILD)/tests/test_bvh: $(BUILD)/tests/obj/test_bvh.o $(BVH_REF) $(UNIT_LIBS) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(THREADS) $^ -o $@ $(LDLIBS)
$(ASAN)/tests/test_bvh: tests/unit/test_bvh.c tests/unit/check.h $(BVH_REF_ASAN) $(UNIT_LIBS_ASAN) | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $(THREADS) -Ilabs $< $(BVH_REF_ASAN) $(UNIT_LIBS_ASAN) -o $@ $(LDLIBS)

# test_hexfloat checks two headers of the grader's.
$(BUILD)/tests/test_hexfloat $(ASAN)/tests/test_hexfloat: tests/grader/hexfloat.h tests/grader/decimal.h

# The unit tests of the grader's sandbox, include scan, memo, test files'
# reader (cases.c) and judging of answers (check.c) link the part alone,
# and what it needs of another part (a prerequisite .c below).
$(GRADER_UNITS:%=$(BUILD)/tests/test_%): $(BUILD)/tests/test_%: tests/unit/test_%.c tests/unit/check.h \
                                         tests/grader/%.c $(GRADER_HDR) $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs $(filter %.c,$^) $(BUILD)/kit/libkit.a -o $@ $(LDLIBS)
$(GRADER_UNITS:%=$(ASAN)/tests/test_%): $(ASAN)/tests/test_%: tests/unit/test_%.c tests/unit/check.h \
                                        tests/grader/%.c $(GRADER_HDR) $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) -Ilabs $(filter %.c,$^) $(ASAN)/kit/libkit.a -o $@ $(LDLIBS)
# check.c reads the kinds of cases from cases.c.
$(BUILD)/tests/test_check $(ASAN)/tests/test_check: tests/grader/cases.c
# terminal.c and lookalike.c read UTF-8 with tests/tools/utf8.c.
$(BUILD)/tests/test_terminal $(ASAN)/tests/test_terminal: tests/tools/utf8.c
$(BUILD)/tests/test_lookalike $(ASAN)/tests/test_lookalike: tests/tools/utf8.c
# The sandbox runs its children in the jail (jail.c), its shell scripts
# through init_sh beside it (built plain in both builds: a sanitized
# program does not fit a test's memory limit).
$(BUILD)/tests/test_sandbox $(ASAN)/tests/test_sandbox: tests/grader/jail.c
$(BUILD)/tests/test_sandbox: | $(BUILD)/tests/init_sh
$(ASAN)/tests/test_sandbox: | $(ASAN)/tests/init_sh
$(BUILD)/tests/init_sh $(ASAN)/tests/init_sh: tests/unit/init_sh.c tests/grader/harness_init.h | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $< -o $@
# own_headers.c reads the names with include_scan.c.
$(BUILD)/tests/test_own_headers $(ASAN)/tests/test_own_headers: tests/grader/include_scan.c
# The hidden tests' unit test (instructor's kit only) links them, the
# oracle, the grader's library (the tests' lists and their judge) and the
# reference, which it holds up against the mistakes; sanitized, it draws
# a tenth of the seeds (what it checks there is the code, not the seeds).
$(BUILD)/tests/test_hidden: tests/unit/test_hidden.c tests/unit/check.h $(BUILD)/grader/hidden.o $(REF_OBJ) \
                            $(BUILD)/oracle/liboracle.a $(BUILD)/grader/libgrader.a $(BUILD)/tools/libtools.a \
                            $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs $(filter-out %.h,$^) -o $@ $(LDLIBS)
$(ASAN)/tests/test_hidden: tests/unit/test_hidden.c tests/unit/check.h $(ASAN)/grader/hidden.o $(REF_ASAN) \
                           $(ASAN)/oracle/liboracle.a $(GRADER_LIB_SRC:tests/grader/%.c=$(ASAN)/grader/%.o) \
                           $(ASAN)/tools/libtools.a \
                           $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) -DSEEDS=30 -DSEEDS_FLAT=100 -Ilabs $(filter-out %.h,$^) -o $@ $(LDLIBS)
# The figures' unit test (instructor's kit only) draws every case of the
# public tests and of some seeds' hidden tests with the grader's figures;
# sanitized, one seed's.
FIGURE_LIBS = $(BUILD)/grader/hidden.o $(BUILD)/oracle/liboracle.a $(BUILD)/grader/libgrader.a \
              $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a
$(BUILD)/tests/test_figures: tests/unit/test_figures.c tests/unit/check.h $(FIGURE_LIBS) | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) -Ilabs $(filter-out %.h,$^) -o $@ $(LDLIBS)
$(ASAN)/tests/test_figures: tests/unit/test_figures.c tests/unit/check.h $(ASAN)/grader/hidden.o \
                            $(ASAN)/oracle/liboracle.a $(GRADER_LIB_SRC:tests/grader/%.c=$(ASAN)/grader/%.o) \
                            $(ASAN)/tools/libtools.a $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) -DSEEDS=1 -Ilabs $(filter-out %.h,$^) -o $@ $(LDLIBS)

# ---- bench: speed against accuracy (tests/bench) ----------------------------
# `make bench` writes out/bench/: results.csv, report.md, plot.svg and more
# (about a minute and a half).  tests/suites/bench.sh runs `bench --quick`.  It links the
# reference solutions and the oracle, so only the instructor's kit has it.
BENCH_SRC  = $(wildcard tests/bench/*.c)
BENCH_OBJ  = $(BENCH_SRC:tests/bench/%.c=$(BUILD)/bench/%.o)
HAVE_BENCH := $(and $(HAVE_SOLUTIONS),$(wildcard tests/oracle/hard.h),$(BENCH_SRC))
# Where the linker happens to put the loops moved the reference/textbook
# ratio by 9%: of six random orders of the same objects, three gave 1.00x
# and three 1.10x.  With every function and loop of the bench and of its
# own copies of the reference's objects starting on a 64-byte boundary,
# six orders gave 0.997x-1.005x (tests/bench/README.md).  Used where the
# compiler takes the flags.  The bench's objects depend on the Makefile,
# whose flags its figures depend on.
BENCH_ALIGN = $(shell $(CC) -falign-functions=64 -falign-loops=64 -Werror -x c -c /dev/null -o /dev/null 2>/dev/null && echo -falign-functions=64 -falign-loops=64)
$(BUILD)/bench/%.o: tests/bench/%.c $(wildcard tests/bench/*.h) $(wildcard tests/oracle/*.h) $(KIT_HDR) Makefile | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(BENCH_ALIGN) -Ilabs -c $< -o $@
$(BUILD)/bench/solutions/%.o: solutions/%.c $(KIT_HDR) Makefile | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(BENCH_ALIGN) -Ilabs -c $< -o $@
# The fast path's sqrt is vectorised only if it need not set errno (no result changes).
$(BUILD)/bench/fastpath.o $(BUILD)/bench/measure.o: CFLAGS += -fno-math-errno
$(BUILD)/bin/bench: $(BENCH_OBJ) $(STAGES:%=$(BUILD)/bench/solutions/%.o) \
                    $(BUILD)/oracle/liboracle.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)
all: $(if $(HAVE_BENCH),$(BUILD)/bin/bench)
# `make bench` also measures the ratio in bench-reordered, the same objects
# linked in the reverse order, and bench's report gives both: the check
# that the placement no longer moves it (tests/bench/README.md).
reverse = $(if $(1),$(call reverse,$(wordlist 2,$(words $(1)),$(1))) $(firstword $(1)))
$(BUILD)/bin/bench-reordered: $(BENCH_OBJ) $(STAGES:%=$(BUILD)/bench/solutions/%.o) \
                              $(BUILD)/oracle/liboracle.a $(BUILD)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(CFLAGS) $(call reverse,$(filter %.o,$^)) $(filter %.a,$^) -o $@ $(LDLIBS)
bench: $(BUILD)/bin/bench $(BUILD)/bin/bench-reordered $(BUILD)/sub/solutions/render
	@mkdir -p out/bench
	$(BUILD)/bin/bench-reordered --ratio-only >out/bench/placement.txt.new && mv out/bench/placement.txt.new out/bench/placement.txt
	$(BUILD)/bin/bench --out out/bench --placement out/bench/placement.txt

# ---- the kit's own tests ---------------------------------------------------
# The renderer with the reference stages, sanitized (tests/suites/render_cli.sh).
$(ASAN)/bin/render-solutions: $(ASAN)/kit/render_main.o $(REF_ASAN) $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $(THREADS) $^ -o $@ $(LDLIBS)

# ---- fuzzing the readers of untrusted input (tests/fuzz) --------------------
# `make fuzz [FUZZ="scene png ..."] [FUZZ_SECONDS=n]` builds each target
# with clang's libFuzzer and the sanitizers, then runs it (tests/fuzz/run.sh).
# Not part of `make test`: a run finds what it finds in its time.
FUZZ_CC    ?= clang
FUZZ_FLAGS  = $(STD) -g -O1 $(FPFLAGS) $(WARN) -fsanitize=fuzzer,address,undefined \
              -fno-sanitize-recover=all
FUZZ_SRC    = $(filter-out labs/kit/render.c labs/kit/closest.c,$(KIT_SRC)) tests/grader/cases.c \
              tests/grader/check.c tests/grader/config.c tests/grader/markup.c \
              tests/grader/figures.c $(wildcard tests/grader/fig_*.c) tests/tools/json_read.c \
              tests/tools/base64.c tests/tools/utf8.c
FUZZ_OBJ    = $(addprefix $(OUT_ROOT)/fuzz/obj/,$(notdir $(FUZZ_SRC:.c=.o)))
$(OUT_ROOT)/fuzz/obj/%.o: labs/kit/%.c $(KIT_HDR) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -c $< -o $@
$(OUT_ROOT)/fuzz/obj/%.o: tests/grader/%.c $(GRADER_HDR) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -Ilabs -c $< -o $@
$(OUT_ROOT)/fuzz/obj/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -c $< -o $@
$(OUT_ROOT)/fuzz/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz.h tests/fuzz/fuzz_public.h $(FUZZ_OBJ) | $$(@D)/.
	$(Q)$(FUZZ_CC) $(FUZZ_FLAGS) -Ilabs $< $(FUZZ_OBJ) -o $@ $(LDLIBS)
fuzz:
	@if [ -f tests/fuzz/run.sh ]; then FUZZ_OUT=$(OUT_ROOT)/fuzz FUZZ_CC=$(FUZZ_CC) sh tests/fuzz/run.sh $(FUZZ); \
	 else echo "make fuzz: only the instructor's kit has the fuzz targets (tests/fuzz)"; exit 2; fi

# ---- the grader itself under the sanitizers (`make sanitize-grader`) --------
# Builds the grader with the address, undefined-behaviour and leak
# sanitizers and runs the suites that grade with it (GRADE= names it to
# them): the reference, the skeleton and the self-test's faulty and
# hostile submissions, their pages, results and gradebooks; and the sorter
# of a class's download (SORTSUBS=), on the downloads its suite makes.  The runners
# and harnesses it uses are the plain build's (a sanitized test would not
# fit the tests' memory limit).  Not part of `make test`: about a minute.
GRADER_ASAN_OBJ = $(GRADER_LIB_SRC:tests/grader/%.c=$(ASAN)/grader/%.o)
GRADE_EXTRA_ASAN = $(if $(GRADE_DEFS),$(ASAN)/grader/hidden.o $(ASAN)/oracle/liboracle.a)
$(ASAN)/grader/%.o: tests/grader/%.c $(GRADER_HDR) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(ASAN)/grader/grade_main.o: tests/grader/grade_main.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) $(GRADE_DEFS) -DGRADER_BUILD='"$(BUILD)"' -Ilabs -c $< -o $@
$(ASAN)/grader/hidden.o: tests/hidden/hidden.c $(GRADER_HDR) $(wildcard tests/oracle/*.h) | $$(@D)/.
	$(Q)$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(ASAN)/bin/grade: $(ASAN)/grader/grade_main.o $(GRADE_EXTRA_ASAN) $(GRADER_ASAN_OBJ) \
                   $(ASAN)/tools/libtools.a $(ASAN)/kit/libkit.a | grader $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $^ -o $@ $(LDLIBS)
$(ASAN)/bin/sortsubs: $(ASAN)/grader/sortsubs_main.o $(GRADER_ASAN_OBJ) $(ASAN)/tools/libtools.a \
                      $(ASAN)/kit/libkit.a | $$(@D)/.
	$(Q)$(CC) $(SAN_LINK) $^ -o $@ $(LDLIBS)
SANITIZE_SUITES = grader.sh report.sh class_page.sh limits.sh signals.sh jail.sh sort_submissions.sh
ifneq ($(wildcard tests/suites/grader.sh),)
sanitize-grader: all $(ASAN)/bin/grade $(ASAN)/bin/sortsubs
	@echo "grading with $(ASAN)/bin/grade, sorting with $(ASAN)/bin/sortsubs (address, undefined-behaviour and leak sanitizers)"
	@GRADE=$(ASAN)/bin/grade SORTSUBS=$(ASAN)/bin/sortsubs sh tests/run.sh $(SANITIZE_SUITES)
else
sanitize-grader:
	@echo "make sanitize-grader: only the instructor's kit has the grader's suites (tests/suites)"; exit 2
endif

# What the tests need built (`make -j2 test-build` builds it on two cores).
test-build: all $(UNIT_ASAN) $(if $(HAVE_SOLUTIONS),$(ASAN)/bin/render-solutions)
test: test-build
	@sh tests/run.sh

clean:
	rm -rf out
