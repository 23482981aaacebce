// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_velocity (verilator -F <this file>), relative to this folder.
prenc_velocity_program.v
prenc_velocity.v
