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
THREADS    = -pthread
LDLIBS     = -lm

# What the targets act on (all accept absolute paths).
SUBMISSION ?= labs
SCENE      ?= labs/scenes/default.scene
SIZE       ?=
PART       ?=
RESULTS    ?=
SUBMISSIONS ?=

BUILD      = out/build
ASAN       = out/asan
STAGES     = part1_image_plane part2_pixel_coordinates part3a_sphere_intersect part3b_ray_color
HAVE_SOLUTIONS := $(wildcard solutions/part1_image_plane.c)

# ---- the framework students use (labs/kit) ---------------------------------
KIT_SRC    = labs/kit/image.c labs/kit/png.c labs/kit/zlib.c labs/kit/scene.c labs/kit/render.c
KIT_HDR    = $(wildcard labs/*.h labs/kit/*.h)
KIT_OBJ    = $(KIT_SRC:labs/kit/%.c=$(BUILD)/kit/%.o)
KIT_ASAN   = $(KIT_SRC:labs/kit/%.c=$(ASAN)/kit/%.o)

.PHONY: all help render compare grade grade-all gradescope student-kit bench \
        handouts test unit-tests clean
.DELETE_ON_ERROR:
.SECONDEXPANSION:

all: $(BUILD)/kit/libkit.a $(BUILD)/bin/compare $(BUILD)/sub/labs/render \
     $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render) unit-tests

help:
	@echo "make render  [SUBMISSION=dir] [SCENE=file] [SIZE=WxH] [OUT=file]"
	@echo "make compare [SUBMISSION=dir] [SCENE=file]"
	@echo "make grade   [SUBMISSION=dir] [PART=1|2|3a|3b] [RESULTS=file]"
	@echo "make grade-all SUBMISSIONS=dir [OUT=dir]"
	@echo "make gradescope | student-kit | bench | handouts | test | clean"

$(BUILD)/kit/%.o: labs/kit/%.c $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(THREADS) -c $< -o $@
$(ASAN)/kit/%.o: labs/kit/%.c $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(SANFLAGS) $(THREADS) -c $< -o $@
$(BUILD)/kit/libkit.a: $(KIT_OBJ)
	rm -f $@ && ar rcs $@ $^
$(ASAN)/kit/libkit.a: $(KIT_ASAN)
	rm -f $@ && ar rcs $@ $^

# ---- renderer and compare, per submission ----------------------------------
# A submission's build lives in out/build/sub/<name>: labs and solutions by
# name, any other directory by its absolute path with / turned into _.
# Stage files the submission lacks come from labs/ (the skeletons).
sub_name   = $(if $(filter labs solutions,$(1)),$(1),$(subst /,_,$(abspath $(1))))
stage_src  = $(firstword $(wildcard $(2)/$(1).c) labs/$(1).c)
SUB_NAME  := $(call sub_name,$(SUBMISSION))
SUB_BUILD  = $(BUILD)/sub/$(SUB_NAME)

$(BUILD)/sub/labs/%.o: labs/%.c $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(BUILD)/sub/solutions/%.o: solutions/%.c $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Ilabs -c $< -o $@
ifeq ($(filter labs solutions,$(SUB_NAME)),)
$(SUB_BUILD)/%.o: $$(call stage_src,$$*,$(SUBMISSION)) $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Ilabs -c $< -o $@
endif
$(BUILD)/sub/%/render: $(BUILD)/kit/render_main.o \
                       $$(addprefix $(BUILD)/sub/$$*/,$$(addsuffix .o,$$(STAGES))) $(BUILD)/kit/libkit.a
	$(CC) $(CFLAGS) $(THREADS) $^ -o $@ $(LDLIBS)
$(BUILD)/bin/compare: $(BUILD)/kit/compare_main.o $(BUILD)/kit/libkit.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)

SCENE_NAME = $(basename $(notdir $(SCENE)))
OUT_RENDER = $(if $(OUT),$(OUT),out/$(SCENE_NAME).png)

render: $(SUB_BUILD)/render
	$(SUB_BUILD)/render "$(SCENE)" $(if $(SIZE),--size $(SIZE)) -o "$(OUT_RENDER)"

# In the kit's own repository the reference image is rendered with
# solutions/; in the student kit it is the stored render under labs/reference.
REF_IMAGE = $(if $(HAVE_SOLUTIONS),out/compare/$(SCENE_NAME)-reference.png,labs/reference/$(SCENE_NAME).png)
compare: $(SUB_BUILD)/render $(BUILD)/bin/compare $(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render)
	@mkdir -p out/compare
	$(SUB_BUILD)/render "$(SCENE)" -o out/compare/$(SCENE_NAME)-submission.png
	$(if $(HAVE_SOLUTIONS),$(BUILD)/sub/solutions/render "$(SCENE)" --quiet -o $(REF_IMAGE))
	$(BUILD)/bin/compare out/compare/$(SCENE_NAME)-submission.png $(REF_IMAGE) \
	    -o out/compare/$(SCENE_NAME).png

# ---- the oracle: independent double-double answers (tests/oracle) ----------
ORACLE_SRC = $(filter-out %_main.c,$(wildcard tests/oracle/*.c))
ORACLE_OBJ = $(ORACLE_SRC:tests/oracle/%.c=$(BUILD)/oracle/%.o)
$(BUILD)/oracle/%.o: tests/oracle/%.c $(wildcard tests/oracle/*.h) $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(ASAN)/oracle/%.o: tests/oracle/%.c $(wildcard tests/oracle/*.h) $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(BUILD)/oracle/liboracle.a: $(ORACLE_OBJ)
	rm -f $@ && ar rcs $@ $^
$(ASAN)/oracle/liboracle.a: $(ORACLE_SRC:tests/oracle/%.c=$(ASAN)/oracle/%.o)
	rm -f $@ && ar rcs $@ $^

# ---- instructor tools: archives (zip, tar.gz) and JSON (tests/tools) -------
TOOLS_SRC  = $(filter-out tests/tools/pack_main.c,$(wildcard tests/tools/*.c))
TOOLS_OBJ  = $(TOOLS_SRC:tests/tools/%.c=$(BUILD)/tools/%.o)
$(BUILD)/tools/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -Ilabs -c $< -o $@
$(ASAN)/tools/%.o: tests/tools/%.c $(wildcard tests/tools/*.h) $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
$(BUILD)/tools/libtools.a: $(TOOLS_OBJ)
	rm -f $@ && ar rcs $@ $^
$(ASAN)/tools/libtools.a: $(TOOLS_SRC:tests/tools/%.c=$(ASAN)/tools/%.o)
	rm -f $@ && ar rcs $@ $^
$(BUILD)/bin/pack: $(BUILD)/tools/pack_main.o $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $^ -o $@ $(LDLIBS)

# ---- unit tests of the framework (tests/unit) ------------------------------
UNIT_SRC   = $(wildcard tests/unit/test_*.c)
UNIT_BIN   = $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
UNIT_ASAN  = $(UNIT_SRC:tests/unit/%.c=$(ASAN)/tests/%)
REF_OBJ    = $(STAGES:%=$(BUILD)/sub/solutions/%.o)
REF_ASAN   = $(STAGES:%=$(ASAN)/sub/solutions/%.o)
unit-tests: $(UNIT_BIN)
$(ASAN)/sub/solutions/%.o: solutions/%.c $(KIT_HDR)
	@mkdir -p $(@D)
	$(CC) $(SANFLAGS) -Ilabs -c $< -o $@
UNIT_LIBS  = $(BUILD)/oracle/liboracle.a $(BUILD)/tools/libtools.a $(BUILD)/kit/libkit.a
UNIT_LIBS_ASAN = $(UNIT_LIBS:$(BUILD)/%=$(ASAN)/%)
$(BUILD)/tests/%: tests/unit/%.c tests/unit/check.h $(REF_OBJ) $(UNIT_LIBS)
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) $(THREADS) -Ilabs $< $(REF_OBJ) $(UNIT_LIBS) -o $@ $(LDLIBS)
$(ASAN)/tests/%: tests/unit/%.c tests/unit/check.h $(REF_ASAN) $(UNIT_LIBS_ASAN)
	@mkdir -p $(@D)
	$(CC) $(SANFLAGS) $(THREADS) -Ilabs $< $(REF_ASAN) $(UNIT_LIBS_ASAN) -o $@ $(LDLIBS)

# ---- the kit's own tests ---------------------------------------------------
test: all $(UNIT_ASAN)
	@sh tests/run.sh

clean:
	rm -rf out
