// SPDX-License-Identifier: Apache-2.0
// prenc_fine_position: the verified position with the fraction of the quarter passed,
// extrapolated to the instant a consumer asks (docs/fine.md).
// Model: prenc.fine.fine_position.FinePosition, which this equals clock for clock.
//
// Fixed point: the velocity and the travel V_FRAC = 32 fractional bits of a quarter
// (per clock), the fraction and the extrapolation FRAC = 16, the table's corrections
// CAL_FRAC = 12.
// - travel: the velocity integrated since pos_hyb's last step (it stops once it is 2
//   quarters or more, past any clamp below). The decoder's step is delayed STEP_DELAY =
//   3 cycles, so that travel restarts on the cycle pos_hyb shows the step, at 0: the
//   fraction starts at the crossed edge. With PHASE_FILTER = 1, after a step in the
//   direction of the last it restarts at 3/4 of the phase against the crossed edge
//   (edge + travel + velocity - the crossed edge, unclamped; 0 if that is half a
//   quarter or more): a running mean of the edges' phases, 1/4 of each new edge's.
// - The fraction: the last step crossed the quarter's lower edge (CW) or its upper
//   edge (CCW); fraction = clamp(edge + travel) to the quarter, [0, 1), or with CAL = 1
//   its true span [c_lo, 1 + c_hi). While pos_valid the fine position's quarter is
//   pos_hyb's: when the next edge is late, the fraction holds at the quarter's end.
// - The extrapolation: + velocity x LOOKAHEAD_HALVES / 2, the clocks from the pins to
//   this block's output (and half a clock for an edge's unknown place in its clock),
//   from the velocity of the clock before, to 2^-16. It is the only way the fine
//   position leaves the verified quarter, by at most |velocity| x LOOKAHEAD_HALVES / 2
//   quarters. LOOKAHEAD_HALVES = 0 turns it off.
// - Without a valid velocity: the fraction is the quarter's middle, nothing is
//   extrapolated, and `interpolated` is 0.
// fine_pos = floor((pos_hyb + fraction) * 2^F) modulo 2^(N + 2 + F): the datasheet's
// h = floor(4 theta) with F more bits, so its top N + 2 bits are the quarter.
//
// Latency: OUTPUT_DELAY = 3 clocks after pos_hyb, through three register stages: (A)
// the fraction clamped, with pos_hyb and the flags; (B) plus the extrapolation; (C) the
// output. The extrapolation's velocity is that of two clocks before the output's stage B.
//
// Parameters
//   N                 code word length, 2..24 (pos_hyb is N + 2 bits)
//   FINE_BITS         F, the fraction's bits, 0..8
//   LOOKAHEAD_HALVES  half clocks of extrapolation, 0..255 (0: off)
//   CAL               1: the quarter's span from the calibration table; 0: nominal
//   PHASE_FILTER      1: the phase is a running mean of the edges' (edges that are off
//                     their places or noisy: prenc_fine's EDGE_TOLERANCE > 0); 0: each
//                     edge's (default)
//
// Ports
//   pos_hyb, pos_valid   prenc_core's
//   step, step_cw        the quadrature decoder's registered step (prenc_core's
//                        sync_step and direction)
//   velocity, velocity_valid   prenc_velocity's (signed, 2^-32 quarter per clock)
//   c_lo, c_hi           with CAL = 1: the corrections of pos_hyb's quarter's edges
//   fine_pos             N + 2 + F bits: quarters and their fraction
//   fine_valid           pos_valid, aligned with fine_pos
//   interpolated         fine_valid, with a valid velocity (else the fraction is fixed)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_fine_position #(
  parameter integer N                = 10,
  parameter integer FINE_BITS        = 8,
  parameter integer LOOKAHEAD_HALVES = 0,
  parameter integer CAL              = 0,
  parameter integer PHASE_FILTER     = 0
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire [N+1:0]           pos_hyb,
  input  wire                   pos_valid,
  input  wire                   step,
  input  wire                   step_cw,
  input  wire [31:0]            velocity,
  input  wire                   velocity_valid,
  input  wire [15:0]            c_lo,
  input  wire [15:0]            c_hi,
  output wire [N+FINE_BITS+1:0] fine_pos,
  output wire                   fine_valid,
  output wire                   interpolated
);

  generate
    if (N < 2 || N > 24) begin : g_bad_n
      initial $display("ERROR: %m: parameter N = %0d is out of range 2..24", N);
      prenc_fine_position_parameter_N_out_of_range_2_to_24 u_stop ();
    end
    if (FINE_BITS < 0 || FINE_BITS > 8) begin : g_bad_fine_bits
      initial $display("ERROR: %m: parameter FINE_BITS = %0d is out of range 0..8", FINE_BITS);
      prenc_fine_position_parameter_FINE_BITS_out_of_range_0_to_8 u_stop ();
    end
    if (LOOKAHEAD_HALVES < 0 || LOOKAHEAD_HALVES > 255) begin : g_bad_lookahead
      initial $display("ERROR: %m: parameter LOOKAHEAD_HALVES = %0d is out of range 0..255",
                       LOOKAHEAD_HALVES);
      prenc_fine_position_parameter_LOOKAHEAD_HALVES_out_of_range_0_to_255 u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_fine_position_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (PHASE_FILTER != 0 && PHASE_FILTER != 1) begin : g_bad_phase_filter
      initial $display("ERROR: %m: parameter PHASE_FILTER = %0d must be 0 or 1", PHASE_FILTER);
      prenc_fine_position_parameter_PHASE_FILTER_must_be_0_or_1 u_stop ();
    end
  endgenerate

  function integer bits_of(input integer value);   // bits of a value >= 0, at least 1
    integer v;
    begin
      bits_of = 1;
      for (v = value / 2; v > 0; v = v / 2) bits_of = bits_of + 1;
    end
  endfunction

  // Fixed point and widths (signed values: their sign bit included).
  localparam integer V_FRAC     = 32;                // velocity, travel
  localparam integer FRAC       = 16;                // fraction, extrapolation
  localparam integer CAL_FRAC   = 12;                // the table's corrections
  localparam integer F          = FINE_BITS;
  localparam integer W          = N + 2 + F;
  localparam integer TB         = V_FRAC + 3;        // travel, signed: below 4 quarters
  localparam integer QB         = FRAC + 5;          // the fraction clamped: below 16 quarters
  // The extrapolation, velocity (below 1/2 quarter a clock, 2^-16: 16 bits) x
  // LOOKAHEAD_HALVES (LB bits): PB bits; the fraction with half of it: XB bits.
  localparam integer LB         = bits_of(LOOKAHEAD_HALVES);
  localparam integer PB         = FRAC + LB;
  localparam integer XB         = ((QB > PB - 1) ? QB : PB - 1) + 1;
  localparam integer OB         = W + XB;            // the output's fraction, sign-extended
  localparam integer STEP_DELAY = 3;
  localparam integer PHASE_SHIFT = 2;                // the phase keeps 1 - 2^-2 of its own

  localparam signed [QB-1:0] ONE       = 1 << FRAC;
  localparam signed [9:0]      LOOKAHEAD = LOOKAHEAD_HALVES[9:0];

  reg [STEP_DELAY-1:0] step_d_reg;
  reg [STEP_DELAY-1:0] cw_d_reg;
  reg signed [TB-1:0]  travel_reg;
  reg                  cw_reg;
  reg signed [PB-1:0]  ext_reg;          // velocity x LOOKAHEAD_HALVES, 2^-16
  reg signed [QB-1:0]  frac_a_reg;       // stage A
  reg signed [QB-1:0]  mid_a_reg;        // the quarter's middle
  reg [N+1:0]          pos_a_reg;
  reg                  valid_a_reg;
  reg                  vv_a_reg;
  reg signed [XB-1:0]  sum_b_reg;        // stage B
  reg signed [QB-1:0]  mid_b_reg;
  reg [N+1:0]          pos_b_reg;
  reg                  valid_b_reg;
  reg                  vv_b_reg;
  reg [W-1:0]          fine_pos_reg;     // stage C
  reg                  valid_reg;
  reg                  interpolated_reg;

  // Stage A: the fraction of the quarter, from the crossed edge, clamped to the
  // quarter's span [lo, hi) (without CAL: [0, 1)), to 2^-16.
  wire [15:0]           c_lo_used = (CAL == 1) ? c_lo : 16'd0;
  wire [15:0]           c_hi_used = (CAL == 1) ? c_hi : 16'd0;
  wire signed [QB-1:0] lo   = $signed({c_lo_used[15], c_lo_used, {(FRAC - CAL_FRAC){1'b0}}});
  wire signed [QB-1:0] hi   = ONE +
                               $signed({c_hi_used[15], c_hi_used, {(FRAC - CAL_FRAC){1'b0}}});
  wire signed [QB-1:0] moved = {{(QB - TB + V_FRAC - FRAC){travel_reg[TB-1]}},
                                  travel_reg[TB-1:V_FRAC-FRAC]};   // floor, 2^-16
  wire signed [QB-1:0] reach = (cw_reg ? lo : hi) + moved;
  wire signed [QB-1:0] clamped = (reach < lo) ? lo : (reach >= hi) ? hi - 1'b1 : reach;
  // PHASE_FILTER: the phase against the crossed edge, edge - crossed (-/+ the quarter's
  // width, below 2 quarters) in travel's units plus the travel as it would be this clock.
  wire signed [TB-1:0]  advanced  = travel_reg + {{(TB - 32){velocity[31]}}, velocity};
  wire signed [QB:0] gap      = cw_reg ? {lo[QB-1], lo} - {hi[QB-1], hi}
                                           : {hi[QB-1], hi} - {lo[QB-1], lo};
  wire signed [TB-1:0]  phase     = advanced +
                                    {gap[TB-V_FRAC+FRAC-1:0], {(V_FRAC - FRAC){1'b0}}};
  wire                  phase_in  = (phase[TB-1:V_FRAC-1] == {(TB - V_FRAC + 1){1'b0}}) ||
                                    ((phase[TB-1:V_FRAC-1] == {(TB - V_FRAC + 1){1'b1}}) &&
                                     (phase[V_FRAC-2:0] != {(V_FRAC - 1){1'b0}}));
  wire                  keep      = (PHASE_FILTER == 1) && (cw_d_reg[STEP_DELAY-1] == cw_reg) &&
                                    velocity_valid && phase_in;
  wire signed [TB-1:0]  kept      = phase - (phase >>> PHASE_SHIFT);
  wire signed [QB:0] span  = {lo[QB-1], lo} + {hi[QB-1], hi};
  // Stage B, C.
  wire signed [XB-1:0]  frac_wide = {{(XB - QB){frac_a_reg[QB-1]}}, frac_a_reg};
  wire signed [XB-1:0]  ext_half  = {{(XB - PB + 1){ext_reg[PB-1]}}, ext_reg[PB-1:1]};
  // The fraction (negative below the quarter's start) sign-extended to the output's width.
  wire signed [OB-1:0]  sum_wide  = {{W{sum_b_reg[XB-1]}}, sum_b_reg};
  wire signed [OB-1:0]  mid_wide  = {{(OB - QB){mid_b_reg[QB-1]}}, mid_b_reg};
  wire signed [OB-1:0]  truncated = sum_wide >>> (FRAC - F);
  wire signed [OB-1:0]  mid_trunc = mid_wide >>> (FRAC - F);
  wire [W-1:0]          fraction  = vv_b_reg ? truncated[W-1:0] : mid_trunc[W-1:0];
  wire [W-1:0]          base      = {pos_b_reg, {F{1'b0}}};
  // The travel goes on while |travel| < 2 quarters (the register's bits: the test beside
  // the carry chain).
  wire                  travel_in = (travel_reg[TB-1:V_FRAC+1] == {(TB - V_FRAC - 1){1'b0}}) ||
                                    ((travel_reg[TB-1:V_FRAC+1] == {(TB - V_FRAC - 1){1'b1}}) &&
                                     (travel_reg[V_FRAC:0] != {(V_FRAC + 1){1'b0}}));
  // The extrapolation's product, from the velocity to 2^-16.
  wire signed [PB-1:0]  v_16      = {{(PB - 32 + V_FRAC - FRAC){velocity[31]}},
                                     velocity[31:V_FRAC-FRAC]};
  wire                  unused_ok = &{1'b0, truncated[OB-1:W], mid_trunc[OB-1:W], span[0],
                                      ext_reg[0],
                                      velocity[V_FRAC-FRAC-1:0], travel_reg[V_FRAC-FRAC-1:0],
                                      gap[QB:TB-V_FRAC+FRAC]};

  always @(posedge clk) begin
    // Stage C.
    fine_pos_reg     <= base + fraction;
    valid_reg        <= valid_b_reg;
    interpolated_reg <= valid_b_reg & vv_b_reg;
    // Stage B.
    sum_b_reg   <= frac_wide + ext_half;
    mid_b_reg   <= mid_a_reg;
    pos_b_reg   <= pos_a_reg;
    valid_b_reg <= valid_a_reg;
    vv_b_reg    <= vv_a_reg;
    // Stage A.
    frac_a_reg  <= clamped;
    mid_a_reg   <= span[QB:1];
    pos_a_reg   <= pos_hyb;
    valid_a_reg <= pos_valid;
    vv_a_reg    <= velocity_valid;
    ext_reg     <= v_16 * LOOKAHEAD;
    // The travel since pos_hyb's last step.
    if (step_d_reg[STEP_DELAY-1]) begin
      cw_reg     <= cw_d_reg[STEP_DELAY-1];
      travel_reg <= keep ? kept : {TB{1'b0}};
    end else if (travel_in) begin
      travel_reg <= advanced;
    end
    step_d_reg <= {step_d_reg[STEP_DELAY-2:0], step};
    cw_d_reg   <= {cw_d_reg[STEP_DELAY-2:0], step_cw};
    if (rst) begin
      step_d_reg       <= {STEP_DELAY{1'b0}};
      cw_d_reg         <= {STEP_DELAY{1'b1}};
      travel_reg       <= {TB{1'b0}};
      cw_reg           <= 1'b1;
      ext_reg          <= {PB{1'b0}};
      frac_a_reg       <= {QB{1'b0}};
      mid_a_reg        <= ONE >>> 1;
      mid_b_reg        <= ONE >>> 1;
      pos_a_reg        <= {(N + 2){1'b0}};
      valid_a_reg      <= 1'b0;
      vv_a_reg         <= 1'b0;
      sum_b_reg        <= {XB{1'b0}};
      pos_b_reg        <= {(N + 2){1'b0}};
      valid_b_reg      <= 1'b0;
      vv_b_reg         <= 1'b0;
      fine_pos_reg     <= {W{1'b0}};
      valid_reg        <= 1'b0;
      interpolated_reg <= 1'b0;
    end
  end

`ifdef FORMAL
  // Properties (formal/prenc_fine_position.sby), for any velocity, steps and
  // corrections: the promise of docs/fine.md. The output is pos_hyb, pos_valid and
  // velocity_valid of OUTPUT_DELAY = 3 clocks before; without a valid velocity the
  // fraction is the quarter's middle; with one, the fine position lies in pos_hyb's
  // quarter, [c_lo, 1 + c_hi) of it with CAL = 1, widened by the extrapolation,
  // floor(velocity x LOOKAHEAD_HALVES / 2), with the velocity of 3 clocks before.
  reg [N+1:0]         f_pos_d1, f_pos_d2, f_pos_d3;
  reg [1:0]           f_valid_d1, f_valid_d2, f_valid_d3;  // {velocity_valid, pos_valid}
  reg signed [15:0]   f_lo_d1, f_lo_d2, f_lo_d3;
  reg signed [15:0]   f_hi_d1, f_hi_d2, f_hi_d3;
  reg signed [31:0]   f_v_d1 = 32'd0, f_v_d2 = 32'd0, f_v_d3 = 32'd0;   // 0 before the
                                                                          // first clocks
  reg [2:0]           f_since_rst = 3'd0;
  always @(posedge clk) begin
    {f_pos_d3, f_pos_d2, f_pos_d1}       <= {f_pos_d2, f_pos_d1, pos_hyb};
    {f_valid_d3, f_valid_d2, f_valid_d1} <= {f_valid_d2, f_valid_d1, velocity_valid, pos_valid};
    {f_lo_d3, f_lo_d2, f_lo_d1}          <= {f_lo_d2, f_lo_d1, c_lo_used};
    {f_hi_d3, f_hi_d2, f_hi_d1}          <= {f_hi_d2, f_hi_d1, c_hi_used};
    {f_v_d3, f_v_d2, f_v_d1}             <= {f_v_d2, f_v_d1, velocity};
    f_since_rst <= rst ? 3'd0 : (f_since_rst == 3'd7) ? 3'd7 : f_since_rst + 1'b1;
  end
  initial assume (rst);
  // The quarter has a width (the table's corrections leave it one); the velocity is
  // below 1/16 quarter a clock (10,000 rpm at N = 10 and 30 MHz: 1/44), so that the
  // bound below does not wrap modulo 2^W.
  always @(*) begin
    assume ($signed(c_hi_used) + 17'sd4096 > $signed(c_lo_used));
    assume ($signed(velocity) < (32'sd1 <<< (V_FRAC - 4)) &&
            $signed(velocity) > -(32'sd1 <<< (V_FRAC - 4)));
  end
  localparam integer F_XB    = FRAC + 13;   // the bound's arithmetic, wide enough for any
                                            // LOOKAHEAD_HALVES
  localparam integer F_SHIFT = FRAC - F;
  localparam integer F_CS    = CAL_FRAC - F;   // the corrections in fraction units
  wire [W-1:0]         f_diff  = fine_pos_reg - {f_pos_d3, {F{1'b0}}};
  wire signed [W:0]    f_error = {f_diff[W-1], f_diff};   // in 2^-F quarters
  wire signed [F_XB-1:0] f_v_16  = $signed(f_v_d3) >>> (V_FRAC - FRAC);   // floor, 2^-16
  wire signed [F_XB-1:0] f_ext   = (f_v_16 * $signed({1'b0, LOOKAHEAD})) >>> 1;
  wire signed [F_XB-1:0] f_ext_q = f_ext >>> F_SHIFT;   // floor, in 2^-F quarters
  wire signed [16:0]   f_lo_q  = $signed({f_lo_d3[15], f_lo_d3}) >>> F_CS;   // floor
  wire signed [16:0]   f_hi_q  = ($signed({f_hi_d3[15], f_hi_d3}) + (17'sd1 <<< F_CS) - 17'sd1)
                                 >>> F_CS;                                     // ceil
  // [floor(c_lo), 1 + ceil(c_hi)) with the extrapolation, in 2^-F quarters.
  wire signed [W:0]    f_lo    = ((CAL == 1) ? f_lo_q[W:0] : 0) +
                                 ((f_ext_q < 0) ? f_ext_q[W:0] : 0);
  wire signed [W:0]    f_hi    = (1 << F) - 1 + ((CAL == 1) ? f_hi_q[W:0] : 0) +
                                 ((f_ext > 0) ? f_ext_q[W:0] + 1 : 0);
  always @(*) begin
    if (f_since_rst >= 3'd3) begin
      assert (valid_reg == f_valid_d3[0]);
      assert (interpolated_reg == (f_valid_d3[0] && f_valid_d3[1]));
      if (!f_valid_d3[1] && CAL == 0)
        assert (fine_pos_reg == {f_pos_d3, {F{1'b0}}} + ((1 << F) >> 1));
      assert (f_error >= f_lo && f_error <= f_hi);
      if (CAL == 0 && LOOKAHEAD_HALVES == 0) assert (fine_pos_reg[W-1:F] == f_pos_d3);
    end
  end
  always @(posedge clk) begin
    if (f_since_rst >= 3'd3) begin
      cover (interpolated_reg && fine_pos_reg[W-1:F] != f_pos_d3);
      cover (interpolated_reg && fine_pos_reg[F-1:0] == {F{1'b1}});
    end
  end
`endif

  assign fine_pos     = fine_pos_reg;
  assign fine_valid   = valid_reg;
  assign interpolated = interpolated_reg;

endmodule

`resetall
