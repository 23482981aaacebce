// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_fine (verilator -F <this file>), relative to this folder.
-F prenc_velocity.f
prenc_tracker.v   // (its divider: prenc_velocity.f's; its ROM check: prenc_cal_lookup.f's)
prenc_period.v    // (its divider: prenc_velocity.f's)
-F prenc_fine_position.f
-F ../cal/prenc_cal_lookup.f
-F ../cal/prenc_decoder_quarter.f
prenc_fine.v
