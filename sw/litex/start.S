// SPDX-License-Identifier: Apache-2.0
// Start-up of the prenc LiteX example's firmware on VexRiscv (RV32I, machine mode):
// the stack, the trap vector, .data copied from ROM, .bss cleared, then main(). A trap
// (the only one enabled is the external interrupt) saves the caller-saved registers,
// calls isr() and returns with mret.
    .section .text.start
    .global _start
_start:
    la      sp, _fstack
    la      t0, trap_entry
    csrw    mtvec, t0
    la      a0, _fdata
    la      a1, _edata
    la      a2, _fdata_rom
1:  beq     a0, a1, 2f
    lw      a3, 0(a2)
    sw      a3, 0(a0)
    addi    a0, a0, 4
    addi    a2, a2, 4
    j       1b
2:  la      a0, _fbss
    la      a1, _ebss
3:  beq     a0, a1, 4f
    sw      zero, 0(a0)
    addi    a0, a0, 4
    j       3b
4:  li      t0, 0x800               // mie.MEIE: external interrupts (mstatus.MIE gates them)
    csrw    mie, t0
    call    main
5:  j       5b

    .balign 4
trap_entry:
    addi    sp, sp, -16*4
    sw      ra,  0*4(sp)
    sw      t0,  1*4(sp)
    sw      t1,  2*4(sp)
    sw      t2,  3*4(sp)
    sw      a0,  4*4(sp)
    sw      a1,  5*4(sp)
    sw      a2,  6*4(sp)
    sw      a3,  7*4(sp)
    sw      a4,  8*4(sp)
    sw      a5,  9*4(sp)
    sw      a6, 10*4(sp)
    sw      a7, 11*4(sp)
    sw      t3, 12*4(sp)
    sw      t4, 13*4(sp)
    sw      t5, 14*4(sp)
    sw      t6, 15*4(sp)
    call    isr
    lw      ra,  0*4(sp)
    lw      t0,  1*4(sp)
    lw      t1,  2*4(sp)
    lw      t2,  3*4(sp)
    lw      a0,  4*4(sp)
    lw      a1,  5*4(sp)
    lw      a2,  6*4(sp)
    lw      a3,  7*4(sp)
    lw      a4,  8*4(sp)
    lw      a5,  9*4(sp)
    lw      a6, 10*4(sp)
    lw      a7, 11*4(sp)
    lw      t3, 12*4(sp)
    lw      t4, 13*4(sp)
    lw      t5, 14*4(sp)
    lw      t6, 15*4(sp)
    addi    sp, sp, 16*4
    mret
