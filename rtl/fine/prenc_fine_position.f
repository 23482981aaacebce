// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_fine_position (verilator -F <this file>), relative to this folder.
prenc_fine_position.v
