// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_datapath, relative to this folder (verilator -F, or -f from rtl/).
prenc_input_conditioner.v
prenc_quadrature.v
prenc_sampler.v
prenc_shift_register.v
prenc_disc_law.v
prenc_predictor.v
prenc_datapath.v
