// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_mode_fsm, relative to this folder.
prenc_mode_fsm.v
