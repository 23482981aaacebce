// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_correlator, relative to this folder (verilator -F, or -f from rtl/).
prenc_correlator.v
prenc_rom_check.v
