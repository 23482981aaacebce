// SPDX-License-Identifier: Apache-2.0
// prenc_velocity: the velocity from windows of the sync track's edges (docs/fine.md).
// Model: prenc.fine.velocity.Velocity, which this equals clock for clock.
//
// The estimator is a program (prenc_velocity_program.v, from sim/prenc/fine/program.py,
// which says what it computes) run by a small engine: one instruction a clock, an
// accumulator (acc), a register (low) that a division shifts its numerator out of and
// its quotient into, and a register file of 32 words in block RAM. Around it, the
// registers that change every clock:
//   now          the clocks, 32 bits (wrapping)
//   count        the steps, 20 bits (wrapping)
//   stime, sposc a step held for the program (pend) until it is done with it: its clock
//                and its edge's place along the motion (count 2^12 plus the crossed
//                edge's correction, signed by the direction; 2^-12 quarter)
//   ltime, lwidth  the last step's clock, and the width less one of the quarter it
//                entered (c_hi - c_lo, clamped to -1/2 .. 3/4 quarter)
//   tick, due    every K = 64 clocks one more update of the speed is due (up to 7):
//                the program, which keeps the speed and its acceleration, integrates
//                one per due tick (FLAG TICK 0) when idle; a fit's load restarts the
//                tick at K / 2 (FLAG TICK 1)
//   velocity     the output: the program's OUT (the signed speed, SIGN)
// A reversal or an illegal transition restarts the program (the velocity 0; an illegal
// transition also drops `valid` and the step held; a reversal's step is held: the first
// window's anchor).
//
// Engine instructions (prenc.fine.engine): LOAD, ADD, SUB (the operand: a word of the
// register file, or with `special` one of now, stime, sposc, ltime, lwidth), HALF n
// (shift right), NUM (low <- acc, acc <- 0), DIV a n (n steps of restoring division by
// a word; `abortable`: a step held, or an update due while the speed accelerates, stops
// it), MUL a n (n steps of shift-and-add), QUOT (acc <- low, saturated to 2^31 - 1),
// STORE a, OUT (the velocity from acc), SIGN (acc <- -acc unless the last step was CW),
// FLAG (the flags; TICK), DONE (the step held is done), JMP (conditions: a step held,
// acc negative, the flags, an update due). The register file's word an instruction reads is
// read the clock before, at the address of the instruction fetched (a program never
// reads a word the instruction before writes).
//
// Latency: the output shows a fitted speed 257 clocks after the step that closed its
// window, extrapolated to the 256th (LATENCY); an update of an accelerating speed up to
// K clocks late while the program is idle, and after its window's work when it is not.
//
// Parameters
//   WINDOW   the window, in clocks (1024 at 30 MHz: 34 us), 32..2^30
//   CAL      1: the corrections c_lo, c_hi are used (a calibration table); 0: not
//   EDGE_TOLERANCE   how far the edges may be off the places the velocity takes them at
//            (the nominal ones: a printed disc without its table; with CAL = 1 the
//            table's: a noisy sensor), 1/1000 slot, 0..60: the windows are whole
//            cycles, the constant-speed test allows that much more error at each edge,
//            and an overdue edge waits for a quarter four times that much wider (its two
//            edges; docs/fine.md: what to set). 0 (default): edges exact to a clock
//
// Ports
//   step, step_cw, illegal   the quadrature decoder's registered outputs
//   c_lo, c_hi   CAL = 1: the corrections of the edges of the quarter the decoder is in
//                after this cycle's step, 2^-12 quarter, two's complement
//   velocity     quarters per clock, signed, 32 fractional bits (below 1/2)
//   valid        the velocity is an estimate (0 after reset and an illegal transition)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_velocity #(
  parameter integer WINDOW         = 1024,
  parameter integer CAL            = 0,
  parameter integer EDGE_TOLERANCE = 0
) (
  input  wire        clk,
  input  wire        rst,
  input  wire        step,
  input  wire        step_cw,
  input  wire        illegal,
  input  wire [15:0] c_lo,
  input  wire [15:0] c_hi,
  output wire [31:0] velocity,
  output wire        valid
);

  generate
    if (WINDOW < 32 || WINDOW > (1 << 30)) begin : g_bad_window
      initial $display("ERROR: %m: parameter WINDOW = %0d is out of range 32..2^30", WINDOW);
      prenc_velocity_parameter_WINDOW_out_of_range_32_to_2_30 u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_velocity_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (EDGE_TOLERANCE < 0 || EDGE_TOLERANCE > 60) begin : g_bad_edge_tolerance
      initial $display("ERROR: %m: parameter EDGE_TOLERANCE = %0d is out of range 0..60",
                       EDGE_TOLERANCE);
      prenc_velocity_parameter_EDGE_TOLERANCE_out_of_range_0_to_60 u_stop ();
    end
  endgenerate

  // Fixed point (prenc.fine.program): speeds 2^-32 quarter per clock, the acceleration
  // 2^-32 per clock^2, places 2^-12 quarter.
  localparam integer CAL_FRAC    = 12;
  localparam integer CB          = 20;            // count
  localparam signed [16:0] WIDTH_LO = -17'sd2048; // the quarter's width less one, clamped
  localparam signed [16:0] WIDTH_HI = 17'sd3072;

  // The register file's constants (prenc.fine.program.constants, RF's order). EDGE:
  // EDGE_TOLERANCE as an edge's error, 2^-12 quarter; with it the windows are whole
  // cycles (C_CYCLE: fewer quarters, no window; then C_QUARTERS more: one cycle).
  localparam integer EDGE       = (EDGE_TOLERANCE * (4 << CAL_FRAC) + 500) / 1000;
  localparam integer CYCLES     = (EDGE_TOLERANCE > 0) ? 1 : 0;
  localparam [31:0] C_WINDOW   = WINDOW;
  localparam [31:0] C_SHORT    = WINDOW / 2;
  localparam [31:0] C_QUARTERS = (CYCLES == 1) ? (1 << CAL_FRAC) : (3 << CAL_FRAC) / 2;
  localparam integer LEVEL_SHIFT = 17;           // LEVEL (below 2^14) 17 bits up: the
                                                 // overdue bound's division takes 35 steps
  localparam [31:0] C_LEVEL0   = ((5 << CAL_FRAC) / 4 + 4 * EDGE) << LEVEL_SHIFT;
  localparam [31:0] C_2DELTA   = ((CAL == 1) ? (32'd2 << 22) : 32'd0)   // 2 x 2^-10 quarter
                               + (EDGE << 21);                        // 2 x EDGE, 2^-32
  localparam [31:0] C_CYCLE    = (CYCLES == 1) ? (7 << CAL_FRAC) / 2 : 0;
  localparam [31:0] C_LATENCY  = 32'd256;
  localparam [31:0] C_OLD      = 32'd1 << 30;
  localparam [31:0] C_ONE      = 32'd1;
  localparam [31:0] C_TWO      = 32'd2;
  // The running mean's weight falls to 1/32 after C_SETTLED windows passed without a
  // trend, more than C_TREND in a row on one side of the speed: with a table and
  // EDGE_TOLERANCE (the sensors' noise); else C_TREND = 0, every window a trend.
  localparam [31:0] C_SETTLED  = 32'd16;
  localparam [31:0] C_TREND    = (CAL == 1 && CYCLES == 1) ? 32'd6 : 32'd0;

  // Opcodes (prenc.fine.engine.OPS; QUOT, 8, is the ROM's `quot` control), specials,
  // out kinds, conditions.
  localparam [3:0] OP_LOAD = 4'd1, OP_ADD = 4'd2, OP_SUB = 4'd3, OP_HALF = 4'd4,
                   OP_NUM = 4'd5, OP_DIV = 4'd6, OP_MUL = 4'd7,
                   OP_STORE = 4'd9, OP_OUT = 4'd10, OP_FLAG = 4'd11, OP_DONE = 4'd12,
                   OP_JMP = 4'd13, OP_WAIT = 4'd14, OP_SIGN = 4'd15;
  localparam [5:0] K_HALF = 6'd32;   // the tick: K = 64 clocks (prenc.fine.program.K)

  // The hardware around the engine.
  reg [31:0]        now_reg;
  reg [CB-1:0]      count_reg;
  reg [31:0]        stime_reg;
  reg [31:0]        sposc_reg;
  reg               pend_reg;
  reg [8:0]         age_reg;        // clocks since the step held (saturating)
  reg [31:0]        ltime_reg;
  reg [31-LEVEL_SHIFT:0] lwidth_reg;   // (the width within -2048 .. 3072: 15 bits)
  reg               cw_reg;
  reg               moved_reg;
  reg [5:0]         tick_reg;       // clocks to the next due update, modulo K
  reg [2:0]         due_reg;        // updates due
  reg               valid_reg;
  reg signed [31:0] velocity_reg;
  // The engine.
  reg [8:0]         pc_reg;
  wire [30:0]       ins;            // the instruction at pc_reg (the ROM's registered word)
  reg [31:0]        acc_reg;
  reg [31:0]        low_reg;
  reg [7:0]         left_reg;       // steps left of DIV, MUL, HALF, while they run
  reg               going_reg;      // ... they run: their first clock is over (DIV's and
                                    // MUL's first clock takes no step)
  reg               ovf_reg;        // a quotient bit went above bit 30
  reg               anch_reg;       // flags
  reg               have_reg;
  reg               bnd_reg;
  reg               stale_reg;      // (a window has passed the test since a change)
  reg               accel_reg;      // (the speed integrates an acceleration)
  // The register file (block RAM). A program never reads a word as it is written
  // (prenc.fine.engine.check), so the block RAM needs no bypass for it (no_rw_check).
  (* no_rw_check *)
  reg [31:0]        rf [0:31];
  reg [31:0]        rd_reg;         // the word the instruction reads
  reg [31:0]        spec_reg;       // ... or its special, registered the clock before
  reg               use_spec_reg;   // ... which of them

  integer i;
  initial begin
    for (i = 0; i < 32; i = i + 1) rf[i] = 32'd0;
    rf[1] = C_WINDOW;
    rf[2] = C_SHORT;
    rf[3] = C_QUARTERS;
    rf[4] = C_LEVEL0;
    rf[5] = C_2DELTA;
    rf[6] = C_LATENCY;
    rf[7] = C_OLD;
    rf[8] = C_ONE;
    rf[9] = C_TWO;
    rf[10] = C_CYCLE;
    rf[11] = C_SETTLED;
    rf[12] = C_TREND;
  end

  // The instruction's fields.
  wire        stepping  = ins[30];   // DIV or MUL          (the adder's controls, decoded
  wire        invert    = ins[29];   // SUB, DIV or SIGN     in the ROM)
  wire        mul       = ins[28];   // MUL
  wire        load      = ins[27];   // LOAD
  wire        quot      = ins[26];   // QUOT
  wire [3:0]  op        = ins[25:22];
  wire        abortable = ins[20];
  wire [4:0]  a         = ins[19:15];
  wire [8:0]  target    = ins[14:6];  // a jump's target; else n, a count or a flag's value
  wire [7:0]  n         = target[7:0];
  wire        next_s    = ins[5];     // the operand of the instruction after this one in the
  wire [4:0]  next_a    = ins[4:0];   // program: a special and its number, or a word's address
  wire        unused_special = ins[21];   // (this instruction's: next_s of the one before)

  // The operand: the register file's word, or the special, both fetched the clock before
  // (DIV's and MUL's: always the register file's).
  wire [31:0] operand = (use_spec_reg && !stepping) ? spec_reg : rd_reg;

  // Iterating instructions: the step count, this one included.
  wire        iterates  = (op == OP_HALF) || (op == OP_DIV) || (op == OP_MUL);
  wire [7:0]  left_now  = going_reg ? left_reg : n;   // the steps left, this one's with
  wire        taking    = stepping && !going_reg;    // DIV's, MUL's first clock: no step
  wire        stay      = (iterates && (taking || left_now != 8'd1)) ||
                          ((op == OP_WAIT) && (age_reg < {1'b0, n}));
  wire        due       = (due_reg != 3'd0) && accel_reg;   // an update of the speed
  wire        abort     = (op == OP_DIV) && abortable && (pend_reg || due);

  // One adder: LOAD 0 + operand, ADD acc + operand, SUB ~(~acc + operand) = acc -
  // operand, SIGN ~acc + 1 = -acc (operand C_ONE; against the CW direction), a
  // division's step ~(~shifted + divisor) = shifted - divisor (it fits without a
  // carry), a multiplication's shifted + operand (when low's top bit is 1).
  // The inversions are on the accumulator's side, off the register file's path. While
  // DIV and MUL step, the register file reads their own operand again (it holds still:
  // nothing is stored meanwhile) and fetches the next instruction's on their last step.
  wire [31:0] shifted   = {acc_reg[30:0], stepping & !mul & low_reg[31]};
  wire [31:0] add_a     = stepping ? (mul ? shifted : ~shifted)
                        : load ? 32'd0 : quot ? (ovf_reg ? 32'h7fff_ffff : low_reg)
                        : invert ? ~acc_reg : acc_reg;
  wire [32:0] sum       = {1'b0, add_a} + {1'b0, operand};
  wire        fits      = !sum[32];   // shifted >= divisor
  wire        high_step = (op == OP_DIV) && going_reg && !abort && (left_reg > 8'd31);
  wire        inverted  = (op == OP_SUB) || ((op == OP_DIV) && fits);   // ~sum: a difference
  wire [31:0] result    = sum[31:0] ^ {32{inverted}};

  // The accumulator's next value: the adder's result, the shifted accumulator (a
  // division's or a multiplication's step that does not add), or as the op says.
  wire        stepping_now = going_reg && ((op == OP_MUL) || ((op == OP_DIV) && !abort));
  wire        adds         = (op == OP_LOAD) || (op == OP_ADD) || (op == OP_SUB) || quot ||
                             ((op == OP_SIGN) && !cw_reg) ||
                             (stepping_now && ((op == OP_MUL) ? low_reg[31] : fits));
  reg  [31:0] acc_next;
  always @(*) begin
    acc_next = acc_reg;
    if (adds) acc_next = result;
    else if (stepping_now) acc_next = shifted;
    else if (op == OP_HALF) acc_next = {acc_reg[31], acc_reg[31:1]};
    else if (op == OP_NUM) acc_next = 32'd0;
  end

  // The conditions.
  reg taken;
  always @(*) begin
    case (a[3:0])
      4'd0:    taken = 1'b1;
      4'd1:    taken = pend_reg;
      4'd2:    taken = acc_reg[31];
      4'd3:    taken = !acc_reg[31];
      4'd4:    taken = have_reg;
      4'd5:    taken = !have_reg;
      4'd6:    taken = anch_reg;
      4'd7:    taken = !anch_reg;
      4'd8:    taken = bnd_reg;
      4'd9:    taken = !bnd_reg;
      4'd10:   taken = stale_reg;
      4'd11:   taken = !stale_reg;
      4'd12:   taken = accel_reg;
      4'd13:   taken = !accel_reg;
      4'd14:   taken = due;
      default: taken = !due;
    endcase
  end

  // The next instruction, read from the ROM. The operand of the instruction after this
  // one in the program is fetched meanwhile (a jump's target, where an abort or a
  // restart goes, reads none: the program is so written).
  wire        restart = illegal || (step && moved_reg && (step_cw != cw_reg));
  wire [8:0]  restart_pc;
  reg  [8:0]  pc_next;
  always @(*) begin
    pc_next = pc_reg + 1'b1;
    if (abort) pc_next = 9'd0;
    else if (stay) pc_next = pc_reg;
    else if (op == OP_JMP && taken) pc_next = target;
    if (restart || rst) pc_next = restart_pc;
  end
  prenc_velocity_program u_program (
    .clk     (clk),
    .pc      (pc_next),
    .word    (ins),
    .restart (restart_pc)
  );

  wire        write  = (op == OP_STORE) && !rst;
  wire [4:0]  read_a = (stepping && stay && !abort) ? a : next_a;   // DIV, MUL: their own
  always @(posedge clk) begin
    if (write) rf[a] <= acc_reg;
    rd_reg <= rf[read_a];
  end

  // The specials, selected for the instruction after this one and registered.
  always @(posedge clk) begin
    use_spec_reg <= next_s;
    case (next_a[2:0])
      3'd0:    spec_reg <= now_reg;
      3'd1:    spec_reg <= stime_reg;
      3'd2:    spec_reg <= sposc_reg;
      3'd3:    spec_reg <= ltime_reg;
      default: spec_reg <= {lwidth_reg, {LEVEL_SHIFT{1'b0}}};
    endcase
  end

  // The tick: every K clocks one more update is due (up to 7); FLAG TICK 0 takes one,
  // FLAG TICK 1 restarts it (K / 2 to go, none due).
  wire        out      = (op == OP_OUT);
  wire        tick     = (op == OP_FLAG) && (a[2:0] == 3'd5);
  wire [2:0]  due_inc  = ((tick_reg == 6'd1) && (due_reg != 3'd7)) ? due_reg + 1'b1 : due_reg;
  wire [2:0]  due_next = (tick && n[0]) ? 3'd0 :
                         (tick && (due_inc != 3'd0)) ? due_inc - 1'b1 : due_inc;

  // The step held, and the quarter's width.
  wire        done     = (op == OP_DONE);
  wire        reversal = step && moved_reg && (step_cw != cw_reg);
  wire        capture  = step && (!pend_reg || done || reversal);
  wire [CB-1:0] count_next = count_reg + 1'b1;
  wire [15:0] crossed  = (CAL == 1) ? (step_cw ? c_lo : c_hi) : 16'd0;
  // The place: count_next 2^12 + (step_cw ? crossed : -crossed), with CAL = 1 -crossed
  // as ~crossed + 1, the 1 in count_next 2^12's low bits (0).
  wire [31:0] place    = (CAL == 1) ? {count_next, {(CAL_FRAC - 1){1'b0}}, ~step_cw} +
                                      ({{16{crossed[15]}}, crossed} ^ {32{~step_cw}})
                                    : {count_next, {CAL_FRAC{1'b0}}};
  wire signed [16:0] width_c = (CAL == 1) ? $signed({c_hi[15], c_hi}) - $signed({c_lo[15], c_lo})
                                          : 17'sd0;
  wire signed [16:0] width_w = (width_c < WIDTH_LO) ? WIDTH_LO : (width_c > WIDTH_HI) ? WIDTH_HI
                                                                                   : width_c;
  wire [15:0]        width   = width_w[15:0];   // (within -2048 .. 3072)
  wire               unused_width = &{1'b0, width_w[16], width[15]};

  always @(posedge clk) begin
    // The engine.
    pc_reg  <= pc_next;
    left_reg  <= taking ? n : left_now - 1'b1;
    going_reg <= stay && iterates && !abort;
    case (op)
      OP_NUM:   low_reg <= acc_reg;
      OP_DIV: begin
        if (!abort && going_reg) begin
          low_reg <= {low_reg[30:0], fits};
        end
      end
      OP_FLAG: begin
        case (a[2:0])
          3'd0:    anch_reg  <= n[0];
          3'd1:    have_reg  <= n[0];
          3'd2:    bnd_reg   <= n[0];
          3'd3:    stale_reg <= n[0];
          3'd4:    accel_reg <= n[0];
          default: ;   // 5: TICK (below)
        endcase
      end
      default: ;
    endcase
    // The quotient's overflow: a bit that fits, in a step whose bit ends above bit 30.
    acc_reg <= acc_next;
    ovf_reg <= (op != OP_NUM) && (ovf_reg || (fits && high_step));
    if (op == OP_MUL) begin
      if (going_reg) low_reg <= {low_reg[30:0], 1'b0};
    end

    // The output, and the tick.
    if (out) begin
      velocity_reg <= acc_reg;
      valid_reg    <= 1'b1;
    end
    if (done) pend_reg <= 1'b0;
    tick_reg <= (tick && n[0]) ? K_HALF : tick_reg - 1'b1;
    due_reg  <= due_next;

    // The steps.
    now_reg <= now_reg + 1'b1;
    if (age_reg != 9'd511) age_reg <= age_reg + 1'b1;
    if (step) begin
      count_reg  <= count_next;
      ltime_reg  <= now_reg;
      lwidth_reg <= width[31-LEVEL_SHIFT:0];
      cw_reg     <= step_cw;
      moved_reg  <= 1'b1;
      if (capture) begin
        age_reg   <= 9'd1;
        stime_reg <= now_reg;
        sposc_reg <= place;
        pend_reg  <= 1'b1;
      end
    end

    // A restart.
    if (restart) begin
      velocity_reg <= 32'sd0;
      acc_reg   <= 32'd0;
      low_reg   <= 32'd0;
      going_reg <= 1'b0;
      ovf_reg   <= 1'b0;
      anch_reg  <= 1'b0;
      have_reg  <= 1'b0;
      bnd_reg   <= 1'b0;
      stale_reg <= 1'b0;
      accel_reg <= 1'b0;
      if (illegal) begin
        valid_reg <= 1'b0;
        pend_reg  <= 1'b0;
        moved_reg <= 1'b0;
      end
    end

    if (rst) begin
      now_reg      <= 32'd0;
      count_reg    <= {CB{1'b0}};
      stime_reg    <= 32'd0;
      sposc_reg    <= 32'd0;
      pend_reg     <= 1'b0;
      age_reg      <= 9'd0;
      ltime_reg    <= 32'd0;
      lwidth_reg   <= {(32 - LEVEL_SHIFT){1'b0}};
      cw_reg       <= 1'b1;
      moved_reg    <= 1'b0;
      tick_reg     <= 6'd0;
      due_reg      <= 3'd0;
      valid_reg    <= 1'b0;
      velocity_reg <= 32'sd0;
      acc_reg      <= 32'd0;
      low_reg      <= 32'd0;
      left_reg     <= 8'd0;
      going_reg    <= 1'b0;
      ovf_reg      <= 1'b0;
      anch_reg     <= 1'b0;
      have_reg     <= 1'b0;
      bnd_reg      <= 1'b0;
      stale_reg    <= 1'b0;
      accel_reg    <= 1'b0;
    end
  end

  assign velocity = velocity_reg;
  assign valid    = valid_reg;

endmodule

`resetall
