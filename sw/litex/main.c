// SPDX-License-Identifier: Apache-2.0
// Firmware of the prenc LiteX example SoC: reads the encoder through prenc_wb's snapshot
// with the generated register header (sw/prenc_wb.h), counts the lost-position
// interrupts, and prints every reading on the SoC's UART, one line each:
//
//   prenc id 70726e63 version 0.12.0 n 10 fine_bits 8
//   pos 1234 valid 1 mode 1 fine 315904 vel -12345678 vvalid 1 lost 0 time 123456
//
// pos is pos_hyb (4 x slot + quarter), fine the fine position (FINE_BITS more bits), vel
// the signed velocity in quarters per clock x 2^32, lost the interrupts taken up to the
// snapshot, time the clock count of the snapshot.
#include <stdint.h>

#include <generated/csr.h>
#include <generated/mem.h>
#include <generated/soc.h>

#include "prenc_wb.h"

#define FIELD(reg, name, value) \
    (((value) & PRENC_WB__##reg##__##name##_bm) >> PRENC_WB__##reg##__##name##_bp)

#define CSR_IRQ_MASK    0xBC0  // VexRiscv's external interrupt mask and pending bits
#define CSR_IRQ_PENDING 0xFC0

static volatile prenc_wb_t *const enc = (volatile prenc_wb_t *)PRENC_BASE;
static volatile uint32_t lost;

static void put_char(char c)
{
    while (uart_txfull_read())
        ;
    uart_rxtx_write((uint8_t)c);
}

static void put_str(const char *s)
{
    while (*s)
        put_char(*s++);
}

static void put_dec(int32_t value)
{
    char digits[11];
    int n = 0;
    uint32_t v = value < 0 ? -(uint32_t)value : (uint32_t)value;
    if (value < 0)
        put_char('-');
    do {
        digits[n++] = (char)('0' + v % 10u);  // RV32I has no divide: libgcc's
        v /= 10u;
    } while (v);
    while (n)
        put_char(digits[--n]);
}

static void put_hex(uint32_t v)
{
    for (int shift = 28; shift >= 0; shift -= 4)
        put_char("0123456789abcdef"[(v >> shift) & 0xFu]);
}

void isr(void);
void isr(void)
{
    uint32_t pending;
    __asm__ volatile("csrr %0, %1" : "=r"(pending) : "i"(CSR_IRQ_PENDING));
    if (pending & (1u << PRENC_INTERRUPT)) {
        uint32_t status = enc->IRQ_STATUS;
        if (status & PRENC_WB__IRQ_STATUS__LOST_VALID_bm)
            lost++;
        enc->IRQ_STATUS = status;  // write 1 to clear
    }
}

int main(void)
{
    uint32_t version = enc->VERSION, params = enc->PARAMS;
    put_str("prenc id ");
    put_hex(enc->ID);
    put_str(" version ");
    put_dec((int32_t)FIELD(VERSION, MAJOR, version));
    put_char('.');
    put_dec((int32_t)FIELD(VERSION, MINOR, version));
    put_char('.');
    put_dec((int32_t)FIELD(VERSION, PATCH, version));
    put_str(" n ");
    put_dec((int32_t)FIELD(PARAMS, N, params));
    put_str(" fine_bits ");
    put_dec((int32_t)FIELD(PARAMS, FINE_BITS, params));
    put_char('\n');

    enc->IRQ_STATUS = PRENC_WB__IRQ_STATUS__LOST_VALID_bm;
    enc->IRQ_ENABLE = PRENC_WB__IRQ_ENABLE__LOST_VALID_bm;
    uint32_t mask = 1u << PRENC_INTERRUPT;
    __asm__ volatile("csrw %0, %1" ::"i"(CSR_IRQ_MASK), "r"(mask));
    __asm__ volatile("csrsi mstatus, 8");  // mstatus.MIE

    for (;;) {
        enc->CTRL = PRENC_WB__CTRL__RESOLUTION_bm | PRENC_WB__CTRL__SNAPSHOT_bm;
        uint32_t status = enc->SNAP_STATUS, lost_then = lost;
        put_str("pos ");
        put_dec((int32_t)FIELD(SNAP_POS_HYB, POS_HYB, enc->SNAP_POS_HYB));
        put_str(" valid ");
        put_dec((int32_t)FIELD(SNAP_STATUS, VALID, status));
        put_str(" mode ");
        put_dec((int32_t)FIELD(SNAP_STATUS, MODE, status));
        put_str(" fine ");
        put_dec((int32_t)enc->SNAP_FINE_POS);
        put_str(" vel ");
        put_dec((int32_t)enc->SNAP_VELOCITY);
        put_str(" vvalid ");
        put_dec((int32_t)FIELD(SNAP_STATUS, VELOCITY_VALID, status));
        put_str(" lost ");
        put_dec((int32_t)lost_then);
        put_str(" time ");
        put_dec((int32_t)enc->SNAP_TIME);
        put_char('\n');
    }
}
