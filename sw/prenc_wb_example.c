// SPDX-License-Identifier: Apache-2.0
// Reading the encoder through prenc_wb with the generated header (sw/prenc_wb.h).
// PRENC_WB_BASE is where your SoC maps the core (a LiteX CSR region, say).
#include <stdint.h>
#include "prenc_wb.h"

#ifndef PRENC_WB_BASE
#define PRENC_WB_BASE 0x40000000u
#endif

#define FIELD(reg, name, value) \
    (((value) & PRENC_WB__##reg##__##name##_bm) >> PRENC_WB__##reg##__##name##_bp)

// A consistent reading: position, status and time latched on one clock.
typedef struct {
    uint32_t pos_hyb;   // 4 * slot + quarter
    uint32_t valid;     // 1: a verified absolute position
    uint32_t mode;      // 0 acquiring, 1 normal, 2/3 reduced, 4 incremental
    uint32_t time;      // clock count when it was latched
} prenc_reading_t;

static int prenc_read(volatile prenc_wb_t *enc, prenc_reading_t *out)
{
    if (FIELD(ID, ID, enc->ID) != PRENC_WB__ID__ID_reset)
        return -1;  // not a prenc_wb at this address
    enc->CTRL = PRENC_WB__CTRL__RESOLUTION_bm | PRENC_WB__CTRL__SNAPSHOT_bm;
    uint32_t status = enc->SNAP_STATUS;
    out->pos_hyb = FIELD(SNAP_POS_HYB, POS_HYB, enc->SNAP_POS_HYB);
    out->valid = FIELD(SNAP_STATUS, VALID, status);
    out->mode = FIELD(SNAP_STATUS, MODE, status);
    out->time = enc->SNAP_TIME;
    return 0;
}

// Interrupt when the position stops being valid.
static void prenc_irq_on_loss(volatile prenc_wb_t *enc)
{
    enc->IRQ_STATUS = PRENC_WB__IRQ_STATUS__LOST_VALID_bm;  // write 1 to clear
    enc->IRQ_ENABLE = PRENC_WB__IRQ_ENABLE__LOST_VALID_bm;
}

int prenc_example(void)
{
    volatile prenc_wb_t *enc = (volatile prenc_wb_t *)PRENC_WB_BASE;
    prenc_reading_t r;
    prenc_irq_on_loss(enc);
    if (prenc_read(enc, &r) != 0 || !r.valid)
        return -1;
    return (int)(r.pos_hyb >> 2);  // the slot
}
