// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_power_on_reset, relative to this folder (verilator -F, or -f from rtl/).
prenc_power_on_reset.v
