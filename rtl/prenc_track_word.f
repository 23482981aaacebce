// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_track_word, relative to this folder.
prenc_disc_law.v
prenc_track_word.v
