// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_matrix_table (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_matrix_table.v
prenc_matrix_fkm.v
../common/prenc_rom_check.v
