// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_datapath (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_input_conditioner.v
prenc_quadrature.v
prenc_sampler.v
prenc_shift_register.v
prenc_disc_law.v
prenc_predictor.v
prenc_datapath.v
