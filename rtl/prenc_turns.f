// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_turns, relative to this folder (verilator -F, or -f from rtl/).
prenc_turns.v
