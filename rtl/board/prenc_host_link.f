// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_host_link (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_crc16.v
prenc_uart_rx.v
prenc_uart_tx.v
prenc_frame_rx.v
prenc_frame_tx.v
prenc_host_link.v
