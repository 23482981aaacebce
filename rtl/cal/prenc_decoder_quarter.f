// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_decoder_quarter (verilator -F <this file>), relative to this folder.
prenc_decoder_quarter.v
