// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_core (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_input_conditioner.v
prenc_quadrature.v
prenc_sampler.v
prenc_position.v
prenc_disc_law.v
prenc_track_word.v
prenc_converter.v
../common/prenc_rom_check.v
prenc_mode_fsm.v
prenc_core.v
