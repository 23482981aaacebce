// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_board, relative to this folder (verilator -F, or -f from rtl/).
prenc_input_conditioner.v
prenc_quadrature.v
prenc_sampler.v
prenc_converter.v
prenc_rom_check.v
prenc_position.v
prenc_disc_law.v
prenc_track_word.v
prenc_mode_fsm.v
prenc_core.v
prenc_crc16.v
prenc_uart_rx.v
prenc_uart_tx.v
prenc_frame_rx.v
prenc_frame_tx.v
prenc_host_link.v
prenc_ssi.v
prenc_turns.v
prenc_biss.v
prenc_board.v
