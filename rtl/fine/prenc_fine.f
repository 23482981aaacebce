// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_fine (verilator -F <this file>), relative to this folder.
-F prenc_velocity.f
-F prenc_fine_position.f
-F ../cal/prenc_cal_lookup.f
prenc_fine.v
