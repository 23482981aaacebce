// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_tracker (verilator -F <this file>), relative to this folder.
-F prenc_divider.f
../common/prenc_rom_check.v
prenc_tracker.v
