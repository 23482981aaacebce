// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_converter, relative to this folder (verilator -F, or -f from rtl/).
prenc_converter.v
prenc_rom_check.v
