// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_converter (verilator -F <this file>), relative to this folder;
// a line `-F <list>` includes another top's list, relative to its own folder.
prenc_converter.v
../common/prenc_rom_check.v
