// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_period (verilator -F <this file>), relative to this folder.
-F prenc_divider.f
prenc_period.v
