// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_icebreaker, relative to this folder.
../../rtl/prenc_input_conditioner.v
../../rtl/prenc_quadrature.v
../../rtl/prenc_sampler.v
../../rtl/prenc_converter.v
../../rtl/prenc_rom_check.v
../../rtl/prenc_position.v
../../rtl/prenc_disc_law.v
../../rtl/prenc_track_word.v
../../rtl/prenc_mode_fsm.v
../../rtl/prenc_core.v
../../rtl/prenc_crc16.v
../../rtl/prenc_uart_rx.v
../../rtl/prenc_uart_tx.v
../../rtl/prenc_frame_rx.v
../../rtl/prenc_frame_tx.v
../../rtl/prenc_host_link.v
../../rtl/prenc_ssi.v
../../rtl/prenc_turns.v
../../rtl/prenc_biss.v
../../rtl/prenc_board.v
../../rtl/prenc_power_on_reset.v
prenc_icebreaker.v
