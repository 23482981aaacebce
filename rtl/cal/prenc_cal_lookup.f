// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_cal_lookup (verilator -F <this file>), relative to this folder.
prenc_cal_lookup.v
../common/prenc_rom_check.v
