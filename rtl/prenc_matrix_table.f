// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_matrix_table, relative to this folder (verilator -F, or -f from rtl/).
prenc_matrix_table.v
prenc_matrix_fkm.v
prenc_rom_check.v
