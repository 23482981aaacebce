// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_sampler, relative to this folder (verilator -F, or -f from rtl/).
prenc_sampler.v
