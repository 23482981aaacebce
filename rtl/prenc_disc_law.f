// SPDX-License-Identifier: Apache-2.0
// Sources of prenc_disc_law, relative to this folder.
prenc_disc_law.v
