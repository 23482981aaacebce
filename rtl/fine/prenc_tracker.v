// SPDX-License-Identifier: Apache-2.0
// prenc_tracker: velocity and acceleration from the sync track's edges by a tracking
// filter whose gains come from a table (a Kalman filter's, computed once for the disc
// and the clock by prenc.fine.tracker_gains; docs/fine.md).
//
// Units: quarters and clocks. The state is fixed point:
//   pos   the predicted position less the last edge crossed, 2^-40 quarter (+-8)
//   vel   quarters per clock, 2^-40 (+-2)
//   acc   quarters per clock^2, 2^-60
// Every clock pos += vel, vel += acc >>> 20. On a step of the decoder (d: +1 or -1 for
// the next edge the same way, 0 for the same edge back after a reversal; with CAL = 1
// plus the edge's correction less the last edge's, c_lo or c_hi in 2^-12 quarter):
// - the innovation e = d - (pos + vel), 2^-20 quarter (saturated), and pos is
//   referred to the new edge (pos + vel - d);
// - the gains: the table's word (read, then registered once more) at the column of
//   |vel| of the clock before (2 an octave) and the bin of the filter's age (its
//   updates since the start). A maneuver halves the age first, not below 4: the
//   innovations' running mean (weight 1/4, in standard deviations: the gain gz) above
//   1. A jump sets it to 4: the last update's innovation above 4 standard deviations
//   (a change of acceleration); the filter then chases: its age holds while the
//   running mean stays above 1/2;
// - four serial multipliers, a mantissa bit a clock (12 clocks), then one shifter, a
//   gain a clock (registered); the corrections land APPLY = 32 clocks after the step
//   as if they had at the step: acc += g2 e, vel += g1 e + 32 (g2 e >>> 20),
//   pos += g0 e + 32 g1 e + 512 (g2 e >>> 20). A step while an update is under way
//   is referred but measures nothing.
// - The start: the first step (after reset, a stop, an illegal transition) is an
//   anchor; the second gives the velocity, a quarter over the clocks between them
//   (prenc_divider), LOAD = 64 clocks later, the position moved on by as many clocks, and
//   the filter starts at age 0. Steps before that are referred; a reversal is an anchor.
// - The output: vel, 0 unless it has the last step's sign; once pos is 2 quarters past
//   the last edge (an edge overdue), a level from the velocity shown falls by about
//   v^2 a clock (a power of two by |vel|'s leading one), reaching 0 within 2.25 to 3
//   predicted quarter periods: a stop (0, valid; the next step is an anchor), as is no
//   step for 2^TIMER_BITS - 1 clocks. An illegal transition drops the velocity (valid
//   0) until the next estimate. So do 3 measured updates in a row whose innovation is a
//   quarter or more (the edges lost: a gain table for a smaller edge error than the
//   disc's can leave the filter in a wrong state), until 3 in a row come closer.
// Model: prenc.fine.tracker.Tracker, which this equals clock for clock.
//
// Latency: the velocity output is registered (the state of the clock before); an
// update lands APPLY = 32 clocks after its step, compensated to the step's instant.
//
// Parameters
//   TIMER_BITS   width of the clocks counted, 12..32 (26: 2.2 s at 30 MHz)
//   GAIN_FILE    the gain table ($readmemh, 1,280 words of 72 bits: prenc.fine.
//                tracker_gains's format, `prenc gains`, for the disc's N and edge
//                error and this clock); a missing or short file stops a simulation
//   CAL          1: the edges at their true places, by the calibration table's
//                corrections c_lo, c_hi (the first velocity: the quarter's true width,
//                its correction clamped to +-1/2, over the clocks); 0: unused
//
// Ports
//   step, step_cw, illegal   the quadrature decoder's registered outputs
//   c_lo, c_hi   with CAL = 1, the corrections of the decoder's quarter's lower and
//                upper edges (after this cycle's step), signed, 2^-12 quarter
//   velocity     quarters per clock, signed, 48 fractional bits (prenc_velocity's unit)
//   accel        quarters per clock per clock, signed, 48 fractional bits
//   valid        the velocity is an estimate (0 after reset, an illegal transition and
//                while the edges are lost)
//   offset       the filtered position: the predicted position past the last edge
//                crossed, signed, 2^-24 quarter (pos's top 28 bits; prenc_fine's
//                TRACKER = 2 makes it the fine position between edges)
//   offset_valid the filter tracks and moves the way the disc last stepped, no edge
//                overdue, the edges not lost, and it measured the last two steps (both
//                from the registers: the state after the clock before)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_tracker #(
  parameter integer TIMER_BITS = 26,
  parameter         GAIN_FILE  = "prenc_gains_n10_30mhz.hex",
  parameter integer CAL        = 0
) (
  input  wire        clk,
  input  wire        rst,
  input  wire        step,
  input  wire        step_cw,
  input  wire        illegal,
  input  wire [15:0] c_lo,
  input  wire [15:0] c_hi,
  output wire [50:0] velocity,
  output wire [49:0] accel,
  output wire        valid,
  output wire [27:0] offset,
  output wire        offset_valid
);

  generate
    if (TIMER_BITS < 12 || TIMER_BITS > 32) begin : g_bad_timer_bits
      initial $display("ERROR: %m: parameter TIMER_BITS = %0d is out of range 12..32", TIMER_BITS);
      prenc_tracker_parameter_TIMER_BITS_out_of_range_12_to_32 u_stop ();
    end
    if (GAIN_FILE == "") begin : g_no_gain_file
      initial $display("ERROR: %m: parameter GAIN_FILE is empty: the tracker needs its gain table");
      prenc_tracker_parameter_GAIN_FILE_is_required u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_tracker_parameter_CAL_must_be_0_or_1 u_stop ();
    end
  endgenerate

  localparam integer TB    = TIMER_BITS;
  localparam integer PB    = 44;   // pos
  localparam integer VB    = 42;   // vel
  localparam integer AB    = 52;   // acc
  localparam integer EB    = 23;   // the innovation
  localparam integer MB    = 12;   // a gain's mantissa
  localparam integer XB    = EB + MB;   // a product
  localparam integer RB    = 52;   // a correction
  localparam integer ZB    = 16;   // bias
  localparam integer CB    = 46;   // the position's and the velocity's corrections
  localparam integer SB    = 48;   // the position's and the velocity's sums
  localparam integer AS    = AB + 1;   // the acceleration's sum
  localparam integer WB    = 72;   // a table word
  localparam integer BINS  = 40;
  localparam integer DEPTH = 32 * BINS;
  localparam integer QB    = 49;   // the divider's quotient (48 fractional bits)
  localparam integer DIV_CLOCKS = QB + 2;
  localparam integer LOAD       = 64;   // clocks from the second step to the first velocity

  generate
    if (DIV_CLOCKS >= LOAD) begin : g_bad_load   // the division must be done at LOAD
      prenc_tracker_DIV_CLOCKS_must_be_below_LOAD u_stop ();
    end
  endgenerate

  localparam [1:0] P_NONE = 2'd0, P_ANCHOR = 2'd1, P_DIVIDE = 2'd2, P_TRACK = 2'd3;
  localparam [5:0] S_READ = 6'd1, S_WORD = 6'd2, S_MUL = 6'd3, S_SHIFT = 6'd15, S_ACC = 6'd16,
                   S_VEL = 6'd17, S_POS = 6'd18, S_BIAS = 6'd19, S_APPLY = 6'd32;

  localparam signed [SB-1:0] ONE       = {{(SB - 41){1'b0}}, 1'b1, 40'd0};   // a quarter
  localparam signed [VB-1:0] V_TOP     = {1'b0, {(VB - 1){1'b1}}};
  localparam [TB-1:0]        TIMER_MAX = {TB{1'b1}};

  // The gain table.
  reg [WB-1:0] gains [0:DEPTH-1];
  initial $readmemh(GAIN_FILE, gains);
`ifndef SYNTHESIS
  generate
    if (GAIN_FILE != "") begin : g_gain_check
      prenc_rom_check #(
        .NAME  ("GAIN_FILE"),
        .FILE  (GAIN_FILE),
        .DEPTH (DEPTH),
        .WIDTH (WB)
      ) u_gain_check ();
    end
  endgenerate
`endif

  // Registers (the model's attributes of the same names).
  reg [1:0]           phase_reg;
  reg                 valid_reg;
  reg signed [VB-1:0] velocity_reg;
  reg                 cw_reg;
  reg [TB-1:0]        since_reg;
  reg signed [PB-1:0] pos_reg;
  reg signed [VB-1:0] vel_reg;
  reg signed [AB-1:0] acc_reg;
  reg [9:0]           age_reg;
  reg signed [ZB-1:0] bias_reg;
  reg                 jump_reg;
  reg                 chase_reg;
  reg                 lost_reg;        // the edges are lost: valid 0
  reg                 measured_reg;    // the last two steps measured (offset_valid)
  reg                 measured_last_reg;
  reg [1:0]           lock_count_reg;  // updates in a row that disagree with lost_reg
  reg [5:0]           seq_reg;
  reg signed [EB-1:0] e_reg;
  reg [10:0]          address_reg;
  reg [WB-1:0]        read_reg;
  reg [WB-1:0]        word_reg;
  reg signed [XB-1:0] product0_reg;
  reg signed [XB-1:0] product1_reg;
  reg signed [XB-1:0] product2_reg;
  reg signed [XB-1:0] product3_reg;
  reg signed [RB-1:0] acc_corr_reg;
  reg signed [CB-1:0] vel_corr_reg;
  reg signed [CB-1:0] pos_corr_reg;
  reg                 negative_reg;
  reg [6:0]           dividing_reg;   // clocks since the division started (wrapping)
  reg                 decaying_reg;
  reg [VB-1:0]        level_reg;
  reg [RB-1:0]        slope_reg;

  // The divider, for the first velocity: 2^48 / the clocks between two steps.
  wire          div_done;
  wire [QB-1:0] quotient;
  reg           div_start;
  reg           div_cancel;

  wire [QB:0] div_num;   // the first velocity's quarter, 2^-48 (below, by CAL)
  prenc_divider #(
    .NUM_BITS      (QB + 1),
    .DEN_BITS      (TB),
    .QUOTIENT_BITS (QB)
  ) u_divider (
    .clk      (clk),
    .rst      (rst),
    .start    (div_start),
    .cancel   (div_cancel),
    .num      (div_num),
    .den      (since_reg),
    .done     (div_done),
    .quotient (quotient)
  );

  // |vel| and its leading one, registered (of the clock before: a carry chain and a
  // priority encoder less on the way to the table's address); the table's column (2 an
  // octave from 2^-21, 0..31).
  wire [VB-2:0] speed = vel_reg[VB-1] ? -vel_reg[VB-2:0] : vel_reg[VB-2:0];
  reg  [5:0]    lead_one;
  integer       i;
  always @(*) begin
    lead_one = 6'd0;
    for (i = 1; i < VB - 1; i = i + 1) begin
      if (speed[i]) lead_one = i[5:0];
    end
  end
  wire          half = (lead_one == 6'd0) ? 1'b0 : speed[lead_one - 6'd1];
  reg  [5:0]    lead_one_reg;
  reg           half_reg;
  always @(posedge clk) begin
    lead_one_reg <= rst ? 6'd0 : lead_one;
    half_reg     <= rst ? 1'b0 : half;
  end
  wire [6:0]    col_raw = {lead_one_reg, half_reg};       // 2 lead_one + half
  wire [4:0]    col = (col_raw < 7'd38) ? 5'd0 : (col_raw > 7'd69) ? 5'd31 : col_raw[4:0] - 5'd6;

  // The age: 4 after a jump, halved on a maneuver (not below 4); and its bin (0..15,
  // then 4 an octave). While chasing, the age holds.
  wire [ZB-1:0] bias_abs = bias_reg[ZB-1] ? -bias_reg : bias_reg;
  wire          maneuver = bias_abs > 16'd256;
  wire          chase    = jump_reg || (chase_reg && bias_abs > 16'd128);
  wire [9:0]    age_half = {1'b0, age_reg[9:1]};
  wire [9:0]    age_used = jump_reg ? 10'd4 : !maneuver ? age_reg
                         : (age_half < 10'd4) ? 10'd4 : age_half;
  reg  [5:0]    age_bin;
  always @(*) begin
    if (age_used[9])      age_bin = 6'd36 + {4'd0, age_used[8:7]};
    else if (age_used[8]) age_bin = 6'd32 + {4'd0, age_used[7:6]};
    else if (age_used[7]) age_bin = 6'd28 + {4'd0, age_used[6:5]};
    else if (age_used[6]) age_bin = 6'd24 + {4'd0, age_used[5:4]};
    else if (age_used[5]) age_bin = 6'd20 + {4'd0, age_used[4:3]};
    else if (age_used[4]) age_bin = 6'd16 + {4'd0, age_used[3:2]};
    else                  age_bin = {2'd0, age_used[3:0]};
  end
  wire [10:0]   address = {1'b0, col, 5'd0} + {3'd0, col, 3'd0} + {5'd0, age_bin};

  // The word's fields: {gz, g2, g1, g0}, each {shift[5:0], mantissa[11:0]}.
  wire [MB-1:0] m0 = word_reg[11:0];
  wire [MB-1:0] m1 = word_reg[29:18];
  wire [MB-1:0] m2 = word_reg[47:36];
  wire [MB-1:0] m3 = word_reg[65:54];
  wire [5:0]    s0 = word_reg[17:12];
  wire [5:0]    s1 = word_reg[35:30];
  wire [5:0]    s2 = word_reg[53:48];
  wire [5:0]    s3 = word_reg[71:66];

  // The multipliers: a mantissa bit a clock, MSB first.
  wire [3:0]          bit_index = 4'd11 - seq_reg[3:0] + 4'd3;   // 11 at S_MUL
  wire signed [XB-1:0] e_wide = {{(XB - EB){e_reg[EB-1]}}, e_reg};
  wire                 mul = (seq_reg >= S_MUL) && (seq_reg < S_SHIFT);

  // The shifter: (value << 24) >>> amount, kept to RB bits and registered; the gains in
  // turn from S_SHIFT on (g2, g1, g0, gz), each used the clock after.
  reg signed [XB-1:0] sh_value;
  reg [5:0]           sh_amount;
  always @(*) begin
    case (seq_reg)
      S_SHIFT: begin
        sh_value  = product2_reg;
        sh_amount = s2;
      end
      S_SHIFT + 6'd1: begin
        sh_value  = product1_reg;
        sh_amount = s1;
      end
      S_SHIFT + 6'd2: begin
        sh_value  = product0_reg;
        sh_amount = s0;
      end
      default: begin   // S_SHIFT + 3
        sh_value  = product3_reg;
        sh_amount = s3;
      end
    endcase
  end
  wire signed [XB+23:0] sh_wide = $signed({sh_value, 24'd0}) >>> sh_amount;
  reg  signed [RB-1:0]  shifted;
  always @(posedge clk) begin
    shifted <= sh_wide[RB-1:0];
  end

  // The decay's slope, about v^2 a clock: 2^(2 lead_one - 38) (v^2 to 4 v^2), at least 1.
  wire [6:0]    slope_shift = {lead_one_reg, 1'b0} - 7'd38;
  wire [RB-1:0] slope = (lead_one_reg < 6'd19) ? {{(RB - 1){1'b0}}, 1'b1}
                                               : {{(RB - 1){1'b0}}, 1'b1} << slope_shift;

  // The output: vel with the last step's sign (else 0), under the decay's level.
  wire          same = cw_reg ? (!vel_reg[VB-1] && (vel_reg != {VB{1'b0}})) : vel_reg[VB-1];
  wire [VB-1:0] magnitude0 = same ? {1'b0, speed} : {VB{1'b0}};
  wire [VB-1:0] magnitude = (decaying_reg && level_reg < magnitude0) ? level_reg : magnitude0;
  wire signed [VB-1:0] shown = (phase_reg != P_TRACK) ? {VB{1'b0}}
                               : cw_reg ? $signed(magnitude) : -$signed(magnitude);

  // The state's sums, saturated when registered (pos and acc to their two's complement
  // range, vel symmetrically, by their top bits: no compare).
  wire signed [SB-1:0] pos_w      = {{(SB - PB){pos_reg[PB-1]}}, pos_reg};
  wire signed [SB-1:0] vel_w      = {{(SB - VB){vel_reg[VB-1]}}, vel_reg};
  wire signed [SB-1:0] acc_step   = {{(SB - AB + 20){acc_reg[AB-1]}}, acc_reg[AB-1:20]};
  wire signed [AS-1:0] acc_w      = {acc_reg[AB-1], acc_reg};
  wire signed [SB-1:0] predicted  = pos_w + vel_w;
  // An edge overdue: pos 2 quarters or more past the last edge, the last step's way.
  localparam signed [PB-1:0] TWO = {{(PB - 42){1'b0}}, 1'b1, 41'd0};
  wire                 overdue    = cw_reg ? (!pos_reg[PB-1] && (pos_reg[PB-2:41] != 2'b00))
                                           : (pos_reg <= -TWO);
  // The acceleration's correction over APPLY = 32 clocks: to the velocity 32 (g2 e >>> 20),
  // to the position 512 (g2 e >>> 20) (32 x 32 / 2 for 32 x 31 / 2).
  wire                 acc_sign   = acc_corr_reg[RB-1];
  wire signed [CB-1:0] acc_corr_v = {{(CB - RB + 15){acc_sign}}, acc_corr_reg[RB-1:15]};
  wire signed [CB-1:0] acc_corr_p = {{(CB - RB + 11){acc_sign}}, acc_corr_reg[RB-1:11]};
  // The first velocity, 2^48 / clocks >> 8, and where the disc is when it loads: LOAD = 64
  // clocks after the step (the division is done after DIV_CLOCKS).
  wire signed [SB-1:0] first_abs  = {{(SB - QB + 8){1'b0}}, quotient[QB-1:8]};
  wire signed [SB-1:0] first_vel  = negative_reg ? -first_abs : first_abs;
  wire signed [SB-1:0] first_pos  = pos_w + {first_vel[SB-7:0], 6'd0};
  // The saturations.
  wire                 pos_fits   = (pos_n[SB-1:PB-1] == {(SB - PB + 1){1'b0}}) ||
                                    (pos_n[SB-1:PB-1] == {(SB - PB + 1){1'b1}});
  wire                 vel_fits   = ((vel_n[SB-1:VB-1] == {(SB - VB + 1){1'b0}}) ||
                                     (vel_n[SB-1:VB-1] == {(SB - VB + 1){1'b1}})) &&
                                    (vel_n[VB-1:0] != {1'b1, {(VB - 1){1'b0}}});
  wire                 acc_fits   = (acc_n[AS-1] == acc_n[AB-1]);
  wire signed [PB-1:0] pos_sat    = pos_fits ? pos_n[PB-1:0]
                                             : {pos_n[SB-1], {(PB - 1){!pos_n[SB-1]}}};
  wire signed [VB-1:0] vel_sat    = vel_fits ? vel_n[VB-1:0] : vel_n[SB-1] ? -V_TOP : V_TOP;
  wire signed [AB-1:0] acc_sat    = acc_fits ? acc_n[AB-1:0]
                                             : {acc_n[AS-1], {(AB - 1){!acc_n[AS-1]}}};
  // A step's edge less the last one (+-1 quarter, or 0 after a reversal); the innovation,
  // and the normalized innovation, saturated likewise.
  wire                 reversal   = (step_cw != cw_reg);
  wire signed [SB-1:0] d_nominal  = reversal ? {SB{1'b0}} : step_cw ? ONE : -ONE;
  wire signed [SB-1:0] d_wide;
  generate
    if (CAL == 1) begin : g_cal
      // The edge crossed and the last one at their true places.
      reg  signed [15:0] c_last_reg;   // the correction of the last edge crossed
      wire signed [15:0] step_c = step_cw ? c_lo : c_hi;
      wire signed [16:0] moved  = {step_c[15], step_c} - {c_last_reg[15], c_last_reg};
      assign d_wide = d_nominal + {{(SB - 45){moved[16]}}, moved, 28'd0};
      // The first velocity: the quarter's true width (its correction within +-1/2).
      wire               high   = (moved > $signed(17'sd2047));
      wire               low    = (moved < -$signed(17'sd2048));
      wire signed [11:0] width  = high ? 12'sd2047 : low ? -12'sd2048 : moved[11:0];
      assign div_num = {2'b01, 48'd0} + {{2{width[11]}}, width, 36'd0};
      always @(posedge clk) begin
        if (rst) c_last_reg <= 16'd0;
        else if (step && !illegal) c_last_reg <= step_c;   // as the step logic below
      end
    end else begin : g_nominal
      assign d_wide = d_nominal;
      assign div_num = {2'b01, 48'd0};
      wire unused_cal = &{1'b0, c_lo, c_hi};
    end
  endgenerate
  wire signed [SB-1:0] e_sum      = d_wide - predicted;
  wire                 e_fits     = (e_sum[SB-1:EB+19] == {(SB - EB - 19){1'b0}}) ||
                                    (e_sum[SB-1:EB+19] == {(SB - EB - 19){1'b1}});
  // The edges lost: LOST = 3 measured updates in a row whose innovation is a quarter or
  // more (e >= 1 or e < -1); as many closer ones in a row find them again.
  localparam [1:0]     LOST       = 2'd3;
  wire signed [EB-1:0] e_sat      = e_fits ? e_sum[EB+19:20]
                                           : {e_sum[SB-1], {(EB - 1){!e_sum[SB-1]}}};
  wire                 far        = e_sat[EB-1] ? (e_sat[EB-1:20] != 3'b111)
                                                : (e_sat[EB-2:20] != 2'b00);
  wire                 z_fits     = (shifted[RB-1:ZB-1] == {(RB - ZB + 1){1'b0}}) ||
                                    (shifted[RB-1:ZB-1] == {(RB - ZB + 1){1'b1}});
  wire signed [ZB-1:0] z          = z_fits ? shifted[ZB-1:0]
                                           : {shifted[RB-1], {(ZB - 1){!shifted[RB-1]}}};
  wire signed [ZB+1:0] z_diff     = {{2{z[ZB-1]}}, z} - {{2{bias_reg[ZB-1]}}, bias_reg};
  wire                 z_jump     = (z > $signed(16'sd1024)) || (z < -$signed(16'sd1024));

  reg [1:0]           phase_n;
  reg                 valid_n;
  reg                 cw_n;
  reg [TB-1:0]        since_n;
  reg signed [SB-1:0] pos_n;
  reg signed [SB-1:0] vel_n;
  reg signed [AS-1:0] acc_n;
  reg [9:0]           age_n;
  reg signed [ZB-1:0] bias_n;
  reg                 jump_n;
  reg                 chase_n;
  reg                 lost_n;
  reg                 measured_n;
  reg                 measured_last_n;
  reg [1:0]           lock_count_n;
  reg [5:0]           seq_n;
  reg signed [EB-1:0] e_n;
  reg [10:0]          address_n;
  reg signed [XB-1:0] product0_n;
  reg signed [XB-1:0] product1_n;
  reg signed [XB-1:0] product2_n;
  reg signed [XB-1:0] product3_n;
  reg signed [RB-1:0] acc_corr_n;
  reg signed [CB-1:0] vel_corr_n;
  reg signed [CB-1:0] pos_corr_n;
  reg                 negative_n;
  reg [6:0]           dividing_n;
  reg                 decaying_n;
  reg [VB-1:0]        level_n;
  reg [RB-1:0]        slope_n;
  reg                 stop;

  always @(*) begin
    phase_n    = phase_reg;
    valid_n    = valid_reg;
    cw_n       = cw_reg;
    since_n    = (since_reg == TIMER_MAX) ? since_reg : since_reg + 1'b1;
    pos_n      = pos_w + vel_w;
    vel_n      = vel_w + acc_step;
    acc_n      = acc_w;
    age_n      = age_reg;
    bias_n     = bias_reg;
    jump_n     = jump_reg;
    chase_n    = chase_reg;
    lost_n     = lost_reg;
    measured_n = measured_reg;
    measured_last_n = measured_last_reg;
    lock_count_n = lock_count_reg;
    seq_n      = (seq_reg != 6'd0) ? seq_reg + 6'd1 : 6'd0;
    e_n        = e_reg;
    address_n  = address_reg;
    product0_n = product0_reg;
    product1_n = product1_reg;
    product2_n = product2_reg;
    product3_n = product3_reg;
    acc_corr_n = acc_corr_reg;
    vel_corr_n = vel_corr_reg;
    pos_corr_n = pos_corr_reg;
    negative_n = negative_reg;
    dividing_n = dividing_reg + 7'd1;
    decaying_n = decaying_reg;
    level_n    = level_reg;
    slope_n    = slope_reg;
    div_start  = 1'b0;
    div_cancel = 1'b0;

    // The update's sequence.
    if (mul) begin
      product0_n = {product0_reg[XB-2:0], 1'b0} + (m0[bit_index] ? e_wide : {XB{1'b0}});
      product1_n = {product1_reg[XB-2:0], 1'b0} + (m1[bit_index] ? e_wide : {XB{1'b0}});
      product2_n = {product2_reg[XB-2:0], 1'b0} + (m2[bit_index] ? e_wide : {XB{1'b0}});
      product3_n = {product3_reg[XB-2:0], 1'b0} + (m3[bit_index] ? e_wide : {XB{1'b0}});
    end
    case (seq_reg)
      S_ACC: acc_corr_n = shifted;
      S_VEL: begin
        vel_corr_n = shifted[CB-1:0] + acc_corr_v;
        pos_corr_n = {shifted[CB-6:0], 5'd0} + acc_corr_p;
      end
      S_POS: pos_corr_n = pos_corr_reg + shifted[CB-1:0];
      S_BIAS: begin
        bias_n = bias_reg + z_diff[ZB+1:2];
        jump_n = z_jump;
      end
      S_APPLY: begin
        pos_n = pos_n + {{(SB - CB){pos_corr_reg[CB-1]}}, pos_corr_reg};
        vel_n = vel_n + {{(SB - CB){vel_corr_reg[CB-1]}}, vel_corr_reg};
        acc_n = acc_n + {acc_corr_reg[RB-1], acc_corr_reg};
        seq_n = 6'd0;
      end
      default: ;
    endcase

    // The first velocity, from the division.
    if (phase_reg == P_DIVIDE && dividing_reg == LOAD[6:0]) begin
      vel_n     = first_vel;
      pos_n     = first_pos;
      acc_n     = {AS{1'b0}};
      phase_n   = P_TRACK;
      valid_n   = 1'b1;
      age_n     = 10'd0;
      bias_n    = {ZB{1'b0}};
      jump_n    = 1'b0;
      chase_n   = 1'b0;
      measured_n      = 1'b1;
      measured_last_n = 1'b1;
    end

    // An overdue edge: the output decays to 0, a stop.
    stop = (since_reg == TIMER_MAX) && (phase_reg != P_NONE);
    if (decaying_reg) begin
      if ({{(RB - VB){1'b0}}, level_reg} <= slope_reg) stop = 1'b1;
      level_n = level_reg - slope_reg[VB-1:0];
    end else if (phase_reg == P_TRACK && seq_reg == 6'd0 && !step && !illegal && overdue) begin
      decaying_n = 1'b1;
      level_n    = cw_reg ? shown : -shown;
      slope_n    = slope;
    end
    if (stop) begin
      phase_n    = P_NONE;
      decaying_n = 1'b0;
      level_n    = {VB{1'b0}};
      pos_n      = {SB{1'b0}};
      vel_n      = {SB{1'b0}};
      acc_n      = {AS{1'b0}};
      seq_n      = 6'd0;
      div_cancel = 1'b1;
    end

    // Events, which win over all the above.
    if (illegal) begin
      phase_n    = P_NONE;
      valid_n    = 1'b0;
      decaying_n = 1'b0;
      level_n    = {VB{1'b0}};
      pos_n      = {SB{1'b0}};
      vel_n      = {SB{1'b0}};
      acc_n      = {AS{1'b0}};
      seq_n      = 6'd0;
      div_cancel = 1'b1;
      since_n    = {{(TB - 1){1'b0}}, 1'b1};
    end else if (step) begin
      cw_n       = step_cw;
      since_n    = {{(TB - 1){1'b0}}, 1'b1};
      decaying_n = 1'b0;
      level_n    = {VB{1'b0}};
      if (phase_reg == P_TRACK && !stop) begin
        pos_n = pos_n - d_wide;
        measured_n      = (seq_reg == 6'd0) && measured_last_reg;
        measured_last_n = (seq_reg == 6'd0);
        if (seq_reg == 6'd0) begin
          e_n        = e_sat;
          if (far != lost_reg) begin
            lock_count_n = lock_count_reg + 2'd1;
            if (lock_count_reg == LOST - 2'd1) begin
              lost_n       = far;
              lock_count_n = 2'd0;
            end
          end else begin
            lock_count_n = 2'd0;
          end
          address_n  = address;
          chase_n    = chase;
          age_n      = (chase || age_used == 10'd1023) ? age_used : age_used + 10'd1;
          product0_n = {XB{1'b0}};
          product1_n = {XB{1'b0}};
          product2_n = {XB{1'b0}};
          product3_n = {XB{1'b0}};
          seq_n      = S_READ;
        end
      end else if (phase_reg == P_ANCHOR && !reversal && !stop) begin
        div_start  = 1'b1;
        negative_n = !step_cw;
        dividing_n = 7'd1;
        phase_n    = P_DIVIDE;
        pos_n      = {SB{1'b0}};
        vel_n      = {SB{1'b0}};
        acc_n      = {AS{1'b0}};
      end else if (phase_reg == P_DIVIDE && !reversal && !stop) begin
        pos_n      = pos_n - d_wide;   // referred, as the velocity is not known yet
      end else begin
        phase_n    = P_ANCHOR;
        pos_n      = {SB{1'b0}};
        vel_n      = {SB{1'b0}};
        acc_n      = {AS{1'b0}};
        seq_n      = 6'd0;
        div_cancel = 1'b1;
      end
    end
  end

  always @(posedge clk) begin
    // The table's word: read into the block RAM's register, then registered once more
    // (the block RAM's output is slow).
    if (seq_reg == S_READ) read_reg <= gains[address_reg];
    if (seq_reg == S_WORD) word_reg <= read_reg;
    phase_reg    <= phase_n;
    valid_reg    <= valid_n;
    velocity_reg <= shown;
    cw_reg       <= cw_n;
    since_reg    <= since_n;
    pos_reg      <= pos_sat;
    vel_reg      <= vel_sat;
    acc_reg      <= acc_sat;
    age_reg      <= age_n;
    bias_reg     <= bias_n;
    jump_reg     <= jump_n;
    chase_reg    <= chase_n;
    lost_reg     <= lost_n;
    measured_reg <= measured_n;
    measured_last_reg <= measured_last_n;
    lock_count_reg <= lock_count_n;
    seq_reg      <= seq_n;
    e_reg        <= e_n;
    address_reg  <= address_n;
    product0_reg <= product0_n;
    product1_reg <= product1_n;
    product2_reg <= product2_n;
    product3_reg <= product3_n;
    acc_corr_reg <= acc_corr_n;
    vel_corr_reg <= vel_corr_n;
    pos_corr_reg <= pos_corr_n;
    negative_reg <= negative_n;
    dividing_reg <= dividing_n;
    decaying_reg <= decaying_n;
    level_reg    <= level_n;
    slope_reg    <= slope_n;
    if (rst) begin
      phase_reg    <= P_NONE;
      valid_reg    <= 1'b0;
      velocity_reg <= {VB{1'b0}};
      cw_reg       <= 1'b1;
      since_reg    <= {TB{1'b0}};
      pos_reg      <= {PB{1'b0}};
      vel_reg      <= {VB{1'b0}};
      acc_reg      <= {AB{1'b0}};
      age_reg      <= 10'd0;
      bias_reg     <= {ZB{1'b0}};
      jump_reg     <= 1'b0;
      chase_reg    <= 1'b0;
      lost_reg     <= 1'b0;
      measured_reg <= 1'b0;
      measured_last_reg <= 1'b0;
      lock_count_reg <= 2'd0;
      seq_reg      <= 6'd0;
      e_reg        <= {EB{1'b0}};
      address_reg  <= 11'd0;
      product0_reg <= {XB{1'b0}};
      product1_reg <= {XB{1'b0}};
      product2_reg <= {XB{1'b0}};
      product3_reg <= {XB{1'b0}};
      acc_corr_reg <= {RB{1'b0}};
      vel_corr_reg <= {CB{1'b0}};
      pos_corr_reg <= {CB{1'b0}};
      negative_reg <= 1'b0;
      dividing_reg <= 7'd0;
      decaying_reg <= 1'b0;
      level_reg    <= {VB{1'b0}};
      slope_reg    <= {RB{1'b0}};
    end
  end

  assign velocity = {{1{velocity_reg[VB-1]}}, velocity_reg, 8'd0};
  assign accel    = {{10{acc_reg[AB-1]}}, acc_reg[AB-1:12]};
  assign valid    = valid_reg && !lost_reg;
  assign offset       = pos_reg[PB-1:PB-28];
  assign offset_valid = (phase_reg == P_TRACK) && !decaying_reg && same && !lost_reg &&
                        measured_reg;

  wire unused = &{1'b0, quotient[7:0], sh_wide[XB+23:RB], z_diff[1:0], shifted[RB-1:CB],
                  div_done, first_vel[SB-1:SB-6]};

endmodule

`resetall
