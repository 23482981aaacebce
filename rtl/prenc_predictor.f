// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_predictor, relative to this folder (verilator -F, or -f from rtl/).
prenc_disc_law.v
prenc_predictor.v
