// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_shift_register, relative to this folder (verilator -F, or -f from rtl/).
prenc_shift_register.v
