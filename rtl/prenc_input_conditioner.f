// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_input_conditioner, relative to this folder (verilator -F, or -f from rtl/).
prenc_input_conditioner.v
