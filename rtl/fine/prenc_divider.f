// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_divider (verilator -F <this file>), relative to this folder.
prenc_divider.v
