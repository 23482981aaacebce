// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_icestick, relative to this folder; `-F <list>` includes a list.
-F ../../rtl/board/prenc_board.f
../../rtl/board/prenc_power_on_reset.v
prenc_icestick.v
