# SPDX-License-Identifier: Apache-2.0
"""The velocity's arithmetic engine: an accumulator, a divider step and a register
file in block RAM, sequenced by a program (rtl/fine/prenc_velocity.v; the program is
prenc.fine.program).

The engine runs one instruction a clock (a division runs one instruction for as many
clocks as it has quotient bits). Registers:

    ACC   32 bits, two's complement (times wrap: a difference of two is right while
          they are less than 2^31 clocks apart)
    LOW   32 bits: a division's numerator, shifted out, and its quotient, shifted in
    RF    32 words of 32 bits, one read and one write a clock (block RAM). An
          instruction's operand is fetched the clock before, while the instruction
          before it runs, for the instruction after it in the program: so an instruction
          must not read the word the one before it writes, and one that a jump goes to
          (or an abort, or a restart) must not read an operand (the model refuses such
          a program). DIV and MUL keep their operand (OP) from their first step.
    flags ANCH (the window has its anchor), HAVE (a speed and the last window are
          known), BND (an overdue edge bounds the speed), STALE (a window has passed
          the constant-speed test since the speed last changed), ACCEL (the speed
          integrates an acceleration: the program updates it when idle)

Instructions (`op a n`): the operand is RF[a], or with `s` the hardware's value `a`
(SPECIALS) as it was the clock before (it is registered with the read of RF).

    LOAD a      ACC <- operand                  ADD a / SUB a   ACC <- ACC +/- operand
    HALF n      ACC <- ACC >> n (arithmetic)    NUM             LOW <- ACC, ACC <- 0
    DIV a n     the divisor RF[a] (below 2^31) taken on the first clock, then n steps of
                restoring division: LOW <- the quotient of (LOW << (n - 32)) / RF[a]; ACC
                the remainder. Abortable: a step pending stops it (the program goes to 0)
    MUL a n     RF[a] taken on the first clock, then n steps of shift-and-add: ACC <-
                LOW's top n bits times RF[a] (the product below 2^32)
    QUOT        ACC <- LOW, or 2^31 - 1 if the quotient needs more than 31 bits
    STORE a     RF[a] <- ACC
    OUT a       the velocity block's output from ACC (OUT_KINDS)
    SIGN a      ACC <- -ACC, as ~ACC + RF[a] (a: C_ONE), unless the last step was CW
    FLAG a n    flag a <- n                     DONE            the step held is done
    JMP c n     if condition c: the next instruction is n (CONDITIONS)
    WAIT n      until the step held is n clocks old (`age`, as the clock began)
"""

from __future__ import annotations

from dataclasses import dataclass

WORD_BITS = 32
RF_WORDS = 32
WORD_MASK = (1 << WORD_BITS) - 1

OPS = ("NOP", "LOAD", "ADD", "SUB", "HALF", "NUM", "DIV", "MUL", "QUOT", "STORE", "OUT", "FLAG",
       "DONE", "JMP", "WAIT", "SIGN")
SPECIALS = ("NOW", "STIME", "SPOSC", "LTIME", "LWIDTH")   # operands besides the RF
FLAGS = ("ANCH", "HAVE", "BND", "STALE", "ACCEL", "TICK")   # TICK: not a flag (see FLAG)
OUT_KINDS = ("VELOCITY",)   # the velocity, signed; valid
CONDITIONS = ("ALWAYS", "PEND", "NEG", "NOT_NEG", "HAVE", "NOT_HAVE", "ANCH", "NOT_ANCH",
              "BND", "NOT_BND", "STALE", "NOT_STALE", "ACCEL", "NOT_ACCEL", "DUE", "NOT_DUE")


@dataclass(frozen=True)
class Instruction:
    op: str
    a: int = 0          # RF address, special, flag, out kind or condition
    n: int = 0          # division steps, flag value or jump target
    special: bool = False
    abortable: bool = False

    def reads(self) -> int | None:
        """The RF word this instruction reads, or None."""
        if self.op in ("LOAD", "ADD", "SUB", "SIGN") and not self.special:
            return self.a
        if self.op in ("DIV", "MUL"):
            return self.a
        return None

    def writes(self) -> int | None:
        return self.a if self.op == "STORE" else None


def signed(value: int, bits: int) -> int:
    value &= (1 << bits) - 1
    return value - (1 << bits) if value >> (bits - 1) else value


def check(program: list[Instruction], restart: int) -> None:
    """Refuse a program that writes RF[0] (the RTL's QUOT adds it), reads a word the
    instruction before writes, or whose instruction a jump (an abort, a restart) goes
    to reads an operand."""
    if any(ins.writes() == 0 for ins in program):
        raise ValueError("a program must not write RF[0]: QUOT adds it, as 0")
    for k, ins in enumerate(program[:-1]):
        w, r = ins.writes(), program[k + 1].reads()
        if w is not None and w == r:
            raise ValueError(f"instruction {k + 1} reads RF[{r}], which instruction {k} writes")
    targets = {ins.n for ins in program if ins.op == "JMP"} | {0, restart}
    for t in sorted(targets):
        ins = program[t]
        if ins.reads() is not None or ins.special:
            raise ValueError(f"instruction {t}, where a jump goes, reads an operand")


class Engine:
    """Clock-level model of the engine: `step(hw)` runs one clock. `hw` gives the
    hardware's values (the SPECIALS, `pend` and `cw`) as the clock began, and returns
    what the instruction does to the velocity block (`out`, `done`)."""

    def __init__(self, program: list[Instruction], constants: dict[int, int], restart: int = 0):
        self.program = program
        check(program, restart)
        self.constants = dict(constants)
        self.restart_at = restart
        self.reset()

    def reset(self) -> None:
        self.rf = [0] * RF_WORDS
        for a, value in self.constants.items():
            self.rf[a] = value & WORD_MASK
        self.restart(0)

    def restart(self, pc: int) -> None:
        self.pc = pc
        self.acc = 0
        self.low = 0
        self.left = 0
        self.ovf = 0
        self.flags = {name: 0 for name in FLAGS}
        self.op = 0
        self.fetch(pc)

    def fetch(self, pc: int, specials: dict[str, int] | None = None) -> None:
        """The operand of the instruction after `pc` in the program, fetched while the
        instruction at `pc` runs (the RF word before this clock's write lands)."""
        following = self.program[min(pc + 1, len(self.program) - 1)]
        self.rd = self.rf[following.reads() or 0]
        self.spec = specials[SPECIALS[following.a]] & WORD_MASK if specials and following.special else 0

    def operand(self, ins: Instruction) -> int:
        return self.spec if ins.special else self.rd

    def condition(self, c: str, pend: int, due: int = 0) -> bool:
        if c == "ALWAYS":
            return True
        if c in ("DUE", "NOT_DUE"):
            return bool(due and self.flags["ACCEL"]) == (c == "DUE")
        if c == "PEND":
            return bool(pend)
        if c == "NEG":
            return bool(self.acc >> (WORD_BITS - 1))
        if c == "NOT_NEG":
            return not self.acc >> (WORD_BITS - 1)
        flag = c.replace("NOT_", "")
        value = bool(self.flags[flag])
        return not value if c.startswith("NOT_") else value

    def step(self, specials: dict[str, int], pend: int, age: int = 0, cw: int = 1, due: int = 0) -> dict:
        """One clock; returns what the velocity block takes from it: `out` (kind, ACC)
        and `done`."""
        ins = self.program[self.pc]
        effects: dict = {}
        pc_next = self.pc + 1
        acc, low = self.acc, self.low
        write = None
        op = ins.op
        if op == "LOAD":
            acc = self.operand(ins)
        elif op in ("ADD", "SUB"):
            x = self.operand(ins)
            acc = acc + x if op == "ADD" else acc - x
        elif op == "HALF":
            if self.left == 0:
                self.left = ins.n
            acc = (acc >> 1) | (acc & (1 << (WORD_BITS - 1)))
            self.left -= 1
            if self.left:
                pc_next = self.pc
        elif op == "MUL":
            if self.left == 0:                 # the first clock takes the operand
                self.left, self.op, pc_next = ins.n, self.rd, self.pc
            else:
                acc = ((acc << 1) + (self.op if low >> (WORD_BITS - 1) else 0)) & WORD_MASK
                low = (low << 1) & WORD_MASK
                self.left -= 1
                if self.left:
                    pc_next = self.pc
        elif op == "NUM":
            low, acc, self.ovf = acc, 0, 0
        elif op == "DIV":
            if ins.abortable and (pend or (due and self.flags["ACCEL"])):
                pc_next, self.left = 0, 0
            elif self.left == 0:               # the first clock takes the divisor
                self.left, self.op, pc_next = ins.n, self.rd, self.pc
            else:
                divisor = self.op
                shifted = (acc << 1) | (low >> (WORD_BITS - 1))   # below 2 divisor < 2^32
                fits = shifted >= divisor
                acc = shifted - divisor if fits else shifted
                # This step's quotient bit ends at bit left - 1 of LOW: 31 and above, the
                # quotient does not fit in 31 bits.
                if fits and self.left > WORD_BITS - 1:
                    self.ovf = 1
                low = ((low << 1) | int(fits)) & WORD_MASK
                self.left -= 1
                if self.left:
                    pc_next = self.pc
        elif op == "QUOT":
            acc = (WORD_MASK >> 1) if self.ovf else low
        elif op == "STORE":
            write = (ins.a, acc)
        elif op == "OUT":
            effects["out"] = (OUT_KINDS[ins.a], acc)
        elif op == "FLAG":
            if FLAGS[ins.a] == "TICK":
                effects["tick"] = ins.n
            else:
                self.flags[FLAGS[ins.a]] = ins.n
        elif op == "DONE":
            effects["done"] = 1
        elif op == "SIGN":
            if not cw:
                acc = (acc ^ WORD_MASK) + self.operand(ins)
        elif op == "JMP":
            if self.condition(CONDITIONS[ins.a], pend, due):
                pc_next = ins.n
        elif op == "WAIT":
            if age < ins.n:
                pc_next = self.pc
        self.acc = acc & WORD_MASK
        self.low = low
        self.fetch(self.pc, specials)
        if write is not None:
            self.rf[write[0]] = write[1]
        self.pc = pc_next
        return effects
