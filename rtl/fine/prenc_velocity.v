// SPDX-License-Identifier: Apache-2.0
// prenc_velocity: velocity and acceleration from the sync track's edge timing.
//
// Units: quarters (quadrature states) and clocks; `velocity` and `accel` are signed
// with FRAC = 48 fractional bits (quarters per clock, quarters per clock squared).
// docs/fine.md gives the conversion to rpm and the method in full; in short:
//
// - Windows between steps over edges of one type (a full sync cycle apart: the A/B
//   phase and duty errors cancel), each at least WINDOW clocks long.
// - When a window closes after another one (n1 quarters in P1 clocks, n2 in P2): if
//   |n1 P2 - n2 P1| < n1 + n2 (the same speed within a clock's quantization), or
//   the last update did not also see an acceleration of the same sign, the velocity
//   is the mean over both windows and accel 0. Otherwise a parabola through the
//   three anchors: a = 2 (n1/P1 - n2/P2) / (P1 + P2), velocity = n1/P1 + a (P1/2 +
//   FULL_CLOCKS) on the cycle it is loaded. Between updates velocity += accel.
// - QUARTER_WINDOWS = 1 (a disc whose edges are accurate, or calibrated): a window
//   closes on a step over any edge; the windows that pass the test together are a run,
//   which stands for the window before (the velocity is the mean over the whole run);
//   a test failed by 16 times its bound fits at once, and a smaller first failure
//   shows the window's own mean n1/P1.
// - ACCEL_FIT = 0 (a small FPGA): no test and no fit; every close after another window
//   loads the mean over both, accel 0 (no multiplier: about half the logic; the
//   velocity lags an acceleration by about a window).
// - Before a window closes (after reset, a stop, an illegal transition): the mean
//   velocity since the window's first step.
// - A reversal restarts the windows; the velocity takes the new sign at once, with the
//   speed the last edge was crossed at, and the acceleration goes on (no means while
//   it is known). Integrating to 0 holds the velocity there, acceleration kept, for
//   the reversal; a step the same way drops the acceleration; no step for 4 times as
//   long as it took to reach 0 is a stop. The velocity is 0 or has the last step's sign.
// - Overdue (the velocity predicts 1.5 quarters since the last step and none came):
//   accel = -3 v / E, which reaches 0, a stop, at two predicted quarter periods. No
//   step for 2^TIMER_BITS - 1 clocks: a stop as well. A stop reads 0 (valid).
// - An illegal transition drops the velocity (`valid` 0) until the next estimate.
//
// - With CAL = 1 (a calibration table, docs/calibration.md): c_lo and c_hi are the
//   corrections of the edges of the decoder's quarter (after this cycle's step), in
//   2^-12 quarters: a window's length is the distance between its edges' true places,
//   n + c(end) - c(start) clockwise, in 2^-12 quarters (the products 12 bits wider: a
//   fit takes 24 clocks longer); overdue is half a quarter past the quarter's true
//   width (1 to 1.875 quarters, from the corrections of the clock before). With CAL = 0
//   they are not used.
//
// One serial divider (prenc_divider) and a serial multiplier do the arithmetic: an
// update takes FULL_CLOCKS; a step that comes while they are busy updates nothing.
// Model: prenc.fine.velocity.Velocity, which this equals clock for clock.
//
// Latency: an update loads velocity and accel FULL_CLOCKS after the step that closed
// the window (the serial divider and multiplier), with ACCEL_FIT = 0 a constant-speed
// update DIV_CLOCKS + 2; between updates they move every clock.
//
// Parameters
//   WINDOW       shortest window in clocks, 16..2^(TIMER_BITS-1)-1 (2048: 68 us at 30 MHz)
//   TIMER_BITS   width of the clocks counted, 12..32 (26: 2.2 s at 30 MHz)
//   CAL          1: window lengths from the calibration table's corrections; 0: nominal
//   QUARTER_WINDOWS  1: windows between any edges, runs, fits at one large failure
//                (for an accurate or calibrated disc); 0: full-cycle windows (printed)
//   ACCEL_FIT    1: an acceleration fitted when windows disagree (default); 0: the mean
//                of the last two windows, no multiplier (needs QUARTER_WINDOWS = 0)
//
// Ports
//   step, step_cw, illegal   the quadrature decoder's registered outputs (prenc_core's
//                            sync_step, direction, sync_illegal)
//   c_lo, c_hi   with CAL = 1: the corrections of the decoder's quarter's edges
//   velocity     quarters per clock, signed, FRAC fractional bits
//   accel        quarters per clock per clock, signed, FRAC fractional bits
//   valid        the velocity is an estimate (0 after reset and an illegal transition)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_velocity #(
  parameter integer WINDOW     = 2048,
  parameter integer TIMER_BITS = 26,
  parameter integer CAL        = 0,
  parameter integer QUARTER_WINDOWS = 0,
  parameter integer ACCEL_FIT  = 1
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
  output wire        valid
);

  generate
    if (TIMER_BITS < 12 || TIMER_BITS > 32) begin : g_bad_timer_bits
      initial $display("ERROR: %m: parameter TIMER_BITS = %0d is out of range 12..32", TIMER_BITS);
      prenc_velocity_parameter_TIMER_BITS_out_of_range_12_to_32 u_stop ();
    end
    if (WINDOW < 16 || WINDOW >= (1 << (TIMER_BITS - 1))) begin : g_bad_window
      initial $display("ERROR: %m: parameter WINDOW = %0d is out of range 16..2^(TIMER_BITS-1)-1",
                       WINDOW);
      prenc_velocity_parameter_WINDOW_out_of_range u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_velocity_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (QUARTER_WINDOWS != 0 && QUARTER_WINDOWS != 1) begin : g_bad_quarter_windows
      initial $display("ERROR: %m: parameter QUARTER_WINDOWS = %0d must be 0 or 1",
                       QUARTER_WINDOWS);
      prenc_velocity_parameter_QUARTER_WINDOWS_must_be_0_or_1 u_stop ();
    end
    if (ACCEL_FIT != 0 && ACCEL_FIT != 1) begin : g_bad_accel_fit
      initial $display("ERROR: %m: parameter ACCEL_FIT = %0d must be 0 or 1", ACCEL_FIT);
      prenc_velocity_parameter_ACCEL_FIT_must_be_0_or_1 u_stop ();
    end
    if (ACCEL_FIT == 0 && QUARTER_WINDOWS != 0) begin : g_bad_fit_windows
      initial $display("ERROR: %m: parameter ACCEL_FIT = 0 needs QUARTER_WINDOWS = 0 %s",
                       "(runs need the constant-speed test)");
      prenc_velocity_parameter_ACCEL_FIT_0_needs_QUARTER_WINDOWS_0 u_stop ();
    end
  endgenerate

  localparam integer FRAC  = 48;
  localparam integer QB    = FRAC + 1;            // quotient bits
  localparam integer VB    = FRAC + 3;            // velocity
  localparam integer AB    = FRAC + 2;            // accel
  localparam integer CB    = 16;                  // edge count
  localparam integer TB    = TIMER_BITS;
  localparam integer CALB  = (CAL == 1) ? 12 : 0; // fractional bits of a window's length
  localparam integer MCB   = CB + CALB;           // a window's length
  localparam integer MB    = ((MCB > TB + 1) ? MCB : TB + 1) + 1;   // multiplier (a spare bit)
  localparam integer PB    = TB + 1 + AB;         // product
  localparam integer LB    = FRAC + 4;            // lead (and its sum)
  localparam integer NB    = 66;                  // numerator (65 used)
  localparam integer DB    = TB + 1;              // denominator
  localparam integer XB    = MCB + TB + 1;        // n1 P2 - n2 P1
  localparam integer DIV_CLOCKS  = QB + 2;
  localparam integer FULL_CLOCKS = 2 * MCB + 3 * DIV_CLOCKS + TB + 8;

  localparam [3:0] S_IDLE = 4'd0, S_MEAN = 4'd1, S_CROSS1 = 4'd2, S_CROSS2 = 4'd3, S_DECIDE = 4'd4,
                   S_CONSTANT = 4'd5, S_FIT_V01 = 4'd6, S_FIT_V12 = 4'd7, S_FIT_D = 4'd8,
                   S_FIT_A = 4'd9, S_FIT_MUL = 4'd10, S_FIT_LOAD = 4'd11, S_DECAY = 4'd12,
                   S_SUMS = 4'd13;

  localparam signed [VB-1:0] V_TOP     = {1'b0, {(VB - 1){1'b1}}};
  localparam signed [LB-1:0] OVERDUE    = {{(LB - FRAC - 1){1'b0}}, 2'b11, {(FRAC - 1){1'b0}}};
  localparam [TB-1:0] TIMER_MAX = {TB{1'b1}};

  // Registers (the model's attributes of the same names) and their next values.
  reg signed [VB-1:0] velocity_reg;
  reg signed [AB-1:0] accel_reg;
  reg valid_reg;
  reg [CB-1:0] count_reg;
  reg cw_reg;
  reg moved_reg;
  reg [VB-2:0] step_speed_reg;
  reg held_reg;
  reg [TB-1:0] zero_at_reg;
  reg [TB-1:0] since_step_reg;
  reg signed [LB-1:0] lead_reg;
  reg have_a_reg;
  reg [CB-1:0] x_a_reg;
  reg [15:0] c_a_reg;
  reg [TB-1:0] since_a_reg;
  reg have_prev_reg;
  reg [MCB-1:0] prev_n_reg;
  reg [TB-1:0] prev_clocks_reg;
  reg [MCB-1:0] n1_reg;
  reg [TB-1:0] p1_reg;
  reg [MCB-1:0] n2_reg;
  reg [TB-1:0] p2_reg;
  reg [3:0] state_reg;
  reg negative_reg;
  reg [QB-1:0] v01_reg;
  reg [XB-2:0] cross_reg;
  reg signed [XB-1:0] diff_reg;
  reg [MCB:0] n_less_reg;
  reg [TB:0] p_sum_reg;
  reg signed [QB:0] d_reg;
  reg signed [PB:0] v_fit_reg;
  reg [5:0] mul_left_reg;
  reg [MB-1:0] multiplier_reg;
  reg signed [AB-1:0] multiplicand_reg;
  reg signed [PB-1:0] product_reg;
  reg decaying_reg;
  reg last_negative_reg;
  reg last_fit_reg;
  reg signed [VB-1:0] velocity_n;
  reg signed [AB-1:0] accel_n;
  reg valid_n;
  reg [CB-1:0] count_n;
  reg cw_n;
  reg moved_n;
  reg [VB-2:0] step_speed_n;
  reg held_n;
  reg [TB-1:0] zero_at_n;
  reg [TB-1:0] since_step_n;
  reg signed [LB-1:0] lead_n;
  reg have_a_n;
  reg [CB-1:0] x_a_n;
  reg [15:0] c_a_n;
  reg [TB-1:0] since_a_n;
  reg have_prev_n;
  reg [MCB-1:0] prev_n_n;
  reg [TB-1:0] prev_clocks_n;
  reg [MCB-1:0] n1_n;
  reg [TB-1:0] p1_n;
  reg [MCB-1:0] n2_n;
  reg [TB-1:0] p2_n;
  reg [3:0] state_n;
  reg negative_n;
  reg [QB-1:0] v01_n;
  reg [XB-2:0] cross_n;
  reg signed [XB-1:0] diff_n;
  reg [MCB:0] n_less_n;
  reg [TB:0] p_sum_n;
  reg signed [QB:0] d_n;
  reg signed [PB:0] v_fit_n;
  reg [5:0] mul_left_n;
  reg [MB-1:0] multiplier_n;
  reg signed [AB-1:0] multiplicand_n;
  reg signed [PB-1:0] product_n;
  reg decaying_n;
  reg last_negative_n;
  reg last_fit_n;

  // The divider.
  reg           div_start;
  reg           div_cancel;
  reg [NB-1:0]  div_num;
  reg [DB-1:0]  div_den;
  wire          div_done;
  wire [QB-1:0] quotient;

  prenc_divider #(
    .NUM_BITS      (NB),
    .DEN_BITS      (DB),
    .QUOTIENT_BITS (QB)
  ) u_divider (
    .clk      (clk),
    .rst      (rst),
    .start    (div_start),
    .cancel    (div_cancel),
    .num      (div_num),
    .den      (div_den),
    .done     (div_done),
    .quotient (quotient)
  );

  // Between events: velocity + accel (saturating), the lead, the timers.
  wire signed [VB+1:0] v_sum = {{2{velocity_reg[VB-1]}}, velocity_reg} +
                               {{(VB + 2 - AB){accel_reg[AB-1]}}, accel_reg};
  // Saturated to +-V_TOP by its bits (no compare: a carry chain less).
  wire                 v_sum_fits = (v_sum[VB+1:VB-1] == 3'b000) || (v_sum[VB+1:VB-1] == 3'b111);
  wire                 v_sum_min  = (v_sum[VB+1:VB-1] == 3'b111) &&
                                  (v_sum[VB-2:0] == {(VB - 1){1'b0}});
  wire signed [VB-1:0] v_int = (!v_sum_fits || v_sum_min) ? (v_sum[VB+1] ? -V_TOP : V_TOP)
                                                          : v_sum[VB-1:0];
  wire                 v_zero = (velocity_reg == {VB{1'b0}});
  // Without a step the velocity never crosses 0: decaying, it stops there; else it is
  // held at 0 with its acceleration, for the reversal that should come. Held for 4 times
  // as long as it took to get there, the disc has stopped.
  wire                 crossing = !v_zero &&
                                  ((v_int == {VB{1'b0}}) || (v_int[VB-1] != velocity_reg[VB-1]));
  wire                 stop   = (crossing && decaying_reg) ||
                                (held_reg && {2'b00, since_step_reg} >= {zero_at_reg, 2'b00});
  wire                 hold   = crossing && !decaying_reg;
  wire signed [LB-1:0] lead_sum = lead_reg + {{(LB - VB){velocity_reg[VB-1]}}, velocity_reg};
  // |lead_sum| < 2 quarters, by its bits; |lead| >= 1.5 quarters, by two compares.
  wire                 lead_sum_in = (lead_sum[LB-1:FRAC+1] == {(LB - FRAC - 1){1'b0}}) ||
                                     ((lead_sum[LB-1:FRAC+1] == {(LB - FRAC - 1){1'b1}}) &&
                                      (lead_sum[FRAC:0] != {(FRAC + 1){1'b0}}));
  // With CAL: the corrections (else 0), the quarter's true width past one quarter
  // (clamped to -1/2..3/8), and the lead at which an edge is overdue.
  wire [15:0]          c_lo_used = (CAL == 1) ? c_lo : 16'd0;
  wire [15:0]          c_hi_used = (CAL == 1) ? c_hi : 16'd0;
  wire signed [16:0]   width_diff = $signed({c_hi_used[15], c_hi_used}) -
                                    $signed({c_lo_used[15], c_lo_used});
  wire signed [16:0]   extra = (width_diff < -17'sd2048) ? -17'sd2048 :
                               (width_diff > 17'sd1536) ? 17'sd1536 : width_diff;
  wire signed [LB-1:0] overdue_next = OVERDUE +
                                      ({{(LB - 17){extra[16]}}, extra} <<< (FRAC - CALB));
  reg signed [LB-1:0]  overdue_level;   // from the corrections of the clock before
  wire                 overdue = (lead_reg >= overdue_level) || (lead_reg <= -overdue_level);
  always @(posedge clk) begin
    overdue_level <= rst ? OVERDUE : overdue_next;
  end
  wire                 timeout = (since_step_reg == TIMER_MAX);
  wire                 idle = (state_reg == S_IDLE);
  wire                 mul_done = (mul_left_reg == 6'd0);
  wire [VB-2:0]        v_abs = velocity_reg[VB-1] ? -velocity_reg[VB-2:0] : velocity_reg[VB-2:0];

  // The multiplier's next bit and the constant-speed test.
  wire                 mul_bit = multiplier_reg[MB-1];   // loaded left-aligned
  wire signed [PB-1:0] product_step = {product_reg[PB-2:0], 1'b0} +
                                      (mul_bit ? {{(PB - AB){multiplicand_reg[AB-1]}},
                                                  multiplicand_reg}
                                               : {PB{1'b0}});
  // (Both products have MCB + TB bits: the difference fits XB.)
  wire signed [XB-1:0] diff = {1'b0, cross_reg} - {1'b0, product_reg[XB-2:0]};
  wire [MCB:0]         n_sum = {1'b0, n1_reg} + {1'b0, n2_reg};
  // |diff| < n1 + n2 by two sums' signs (n_less = n1 + n2 - 1, P1 + P2: registered
  // while the products run): diff + n_less >= 0 and n_less - diff >= 0.
  wire [XB-1:0]        n_less_wide = {{(XB - MCB - 1){1'b0}}, n_less_reg};
  wire [XB-1:0]        above_low  = diff_reg + n_less_wide;
  wire [XB-1:0]        below_high = n_less_wide - diff_reg;
  // (ACCEL_FIT = 0: the test always passes, and the multiplier is never started.)
  wire                 constant = (ACCEL_FIT == 0) || (!above_low[XB-1] && !below_high[XB-1]);
  // Quarter windows: |diff| < 16 (n1 + n2) likewise (16 n_less + 15), else a fit at once.
  wire [XB-1:0]        n_less_16 = {n_less_wide[XB-5:0], 4'b1111};
  wire [XB-1:0]        above_low_16  = diff_reg + n_less_16;
  wire [XB-1:0]        below_high_16 = n_less_16 - diff_reg;
  wire                 big = (QUARTER_WINDOWS == 1) && (above_low_16[XB-1] || below_high_16[XB-1]);
  // An acceleration that lasts: failed twice with the same sign, or by 16 times the bound.
  wire                 lasting = big || ((diff_reg[XB-1] == last_negative_reg) && last_fit_reg);
  // Quarter windows: a window that passes joins the run, while it stays below
  // 2^(MCB-1) quarters and 2^(TB-1) clocks.
  wire [MCB:0]         n_run = n_less_reg + 1'b1;
  wire                 run_fits = (n_run[MCB:MCB-1] == 2'b00) && (p_sum_reg[TB:TB-1] == 2'b00);
  // The fit's acceleration difference and the velocity it loads.
  wire signed [QB:0]   d = {1'b0, v01_reg} - {1'b0, quotient};
  wire [QB:0]          d_abs = d_reg[QB] ? -d_reg : d_reg;
  wire signed [AB-1:0] accel_fit = negative_reg ? -{1'b0, quotient} : {1'b0, quotient};
  wire signed [PB:0]   v_fit_sum = (cw_reg ? {{(PB - QB + 1){1'b0}}, v01_reg}
                                           : -{{(PB - QB + 1){1'b0}}, v01_reg}) +
                                   {product_reg[PB-1], product_reg};
  // Saturated by its bits, as v_int.
  wire                 v_fit_fits = (v_fit_reg[PB:VB-1] == {(PB - VB + 2){1'b0}}) ||
                                    (v_fit_reg[PB:VB-1] == {(PB - VB + 2){1'b1}});
  wire                 v_fit_min  = (v_fit_reg[PB:VB-1] == {(PB - VB + 2){1'b1}}) &&
                                    (v_fit_reg[VB-2:0] == {(VB - 1){1'b0}});
  wire signed [VB-1:0] v_fit = (!v_fit_fits || v_fit_min) ? (v_fit_reg[PB] ? -V_TOP : V_TOP)
                                                          : v_fit_reg[VB-1:0];
  wire                 v_fit_wrong = (v_fit == {VB{1'b0}}) || (v_fit[VB-1] == cw_reg);
  wire signed [VB-1:0] v_quotient = negative_reg ? -{{(VB - QB){1'b0}}, quotient}
                                                 : {{(VB - QB){1'b0}}, quotient};
  // The multiplier's operands, zero-extended to its width (then loaded left-aligned).
  wire [MB-1:0]        n2_wide = {{(MB - MCB){1'b0}}, n2_reg};
  wire [TB:0]          fit_value = {1'b0, p1_reg[TB-1:1]} + FULL_CLOCKS[TB:0];
  wire [MB-1:0]        fit_multiplier = {{(MB - TB - 1){1'b0}}, fit_value};
  // The step: the edge crossed and how far it is from anchor A.
  wire [CB-1:0]        x = step_cw ? count_reg + 1'b1 : count_reg;
  wire [CB-1:0]        x_diff = x - x_a_reg;
  wire [CB-1:0]        n = x_diff[CB-1] ? -x_diff : x_diff;
  wire                 reversal = moved_reg && (step_cw != cw_reg);
  // The window's length in 2^-CALB quarters, between its edges' true places (step_c:
  // the crossed edge's correction; c_a_reg: A's), at least one LSB.
  wire [15:0]          step_c = step_cw ? c_lo_used : c_hi_used;
  wire signed [16:0]   step_c_wide = $signed({step_c[15], step_c});
  wire signed [16:0]   c_a_wide = $signed({c_a_reg[15], c_a_reg});
  wire signed [16:0]   c_diff = step_cw ? step_c_wide - c_a_wide : c_a_wide - step_c_wide;
  wire signed [MCB+1:0] n_cal_sum = ($signed({{(CALB + 2){1'b0}}, n}) <<< CALB) +
                                    {{(MCB + 2 - 17){c_diff[16]}}, c_diff};
  wire                 n_cal_low = n_cal_sum[MCB+1] || (n_cal_sum == {(MCB + 2){1'b0}});
  wire [MCB-1:0]       n_cal = n_cal_low ? {{(MCB - 1){1'b0}}, 1'b1} : n_cal_sum[MCB-1:0];
  wire [MB-1:0]        n_wide = {{(MB - MCB){1'b0}}, n_cal};
  wire                 closes = (QUARTER_WINDOWS == 1 || n[1:0] == 2'b00) &&
                                (since_a_reg >= WINDOW[TB-1:0]);

  reg [VB-2:0] speed;

  always @(*) begin
    velocity_n = velocity_reg;
    accel_n = accel_reg;
    valid_n = valid_reg;
    count_n = count_reg;
    cw_n = cw_reg;
    moved_n = moved_reg;
    step_speed_n = step_speed_reg;
    held_n = held_reg;
    zero_at_n = zero_at_reg;
    since_step_n = since_step_reg;
    lead_n = lead_reg;
    have_a_n = have_a_reg;
    x_a_n = x_a_reg;
    c_a_n = c_a_reg;
    since_a_n = since_a_reg;
    have_prev_n = have_prev_reg;
    prev_n_n = prev_n_reg;
    prev_clocks_n = prev_clocks_reg;
    n1_n = n1_reg;
    p1_n = p1_reg;
    n2_n = n2_reg;
    p2_n = p2_reg;
    state_n = state_reg;
    negative_n = negative_reg;
    v01_n = v01_reg;
    cross_n = cross_reg;
    diff_n = diff_reg;
    n_less_n = n_less_reg;
    p_sum_n = p_sum_reg;
    d_n = d_reg;
    v_fit_n = v_fit_reg;
    mul_left_n = mul_left_reg;
    multiplier_n = multiplier_reg;
    multiplicand_n = multiplicand_reg;
    product_n = product_reg;
    decaying_n = decaying_reg;
    last_negative_n = last_negative_reg;
    last_fit_n = last_fit_reg;
    div_start = 1'b0;
    div_cancel = 1'b0;
    div_num = {NB{1'b0}};
    div_den = {DB{1'b0}};

    // Between events.
    velocity_n = held_reg ? velocity_reg : v_int;
    if (lead_sum_in) lead_n = lead_sum;
    if (since_step_reg != TIMER_MAX) since_step_n = since_step_reg + 1'b1;
    if (since_a_reg != TIMER_MAX) since_a_n = since_a_reg + 1'b1;

    // The serial multiplier: a bit of the multiplier a cycle, MSB first.
    if (ACCEL_FIT == 1 && (state_reg == S_CROSS1 || state_reg == S_CROSS2 ||
                           state_reg == S_FIT_MUL) && !mul_done) begin
      product_n = product_step;
      mul_left_n = mul_left_reg - 1'b1;
      multiplier_n = multiplier_reg << 1;
    end

    // The sequencer.
    case (state_reg)
      S_MEAN, S_CONSTANT: if (div_done) begin
        velocity_n = v_quotient;
        accel_n = {AB{1'b0}};
        valid_n = 1'b1;
        state_n = S_IDLE;
      end
      S_CROSS1: if (ACCEL_FIT == 1 && mul_done) begin
        cross_n = product_reg[XB-2:0];
        n_less_n = n_sum - 1'b1;
        p_sum_n = {1'b0, p1_reg} + {1'b0, p2_reg};
        multiplier_n = n2_wide << (MB - MCB);
        multiplicand_n = {{(AB - TB){1'b0}}, p1_reg};
        mul_left_n = MCB[5:0];
        product_n = {PB{1'b0}};
        state_n = S_CROSS2;
      end
      S_CROSS2: if (ACCEL_FIT == 1 && mul_done) begin
        diff_n = diff;
        state_n = S_DECIDE;
      end
      S_SUMS: if (ACCEL_FIT == 0) begin  // the two windows' sums, then the mean
        n_less_n = n_sum - 1'b1;
        p_sum_n = {1'b0, p1_reg} + {1'b0, p2_reg};
        state_n = S_DECIDE;
      end
      S_DECIDE: begin
        last_negative_n = diff_reg[XB-1];
        last_fit_n = !constant;
        div_start = 1'b1;
        if (constant || !lasting) begin
          state_n = S_CONSTANT;
          if (QUARTER_WINDOWS == 1 && !constant) begin
            // Quarter windows, one failure: the window's own mean (the run is stale).
            div_num = {{(NB - MCB - FRAC + CALB){1'b0}}, n1_reg, {(FRAC - CALB){1'b0}}};
            div_den = {1'b0, p1_reg};
          end else begin
            div_num = {{(NB - MCB - 1 - FRAC + CALB){1'b0}}, n_run, {(FRAC - CALB){1'b0}}};
            div_den = p_sum_reg;
          end
          if (QUARTER_WINDOWS == 1 && constant && run_fits) begin
            prev_n_n = n_run[MCB-1:0];
            prev_clocks_n = p_sum_reg[TB-1:0];
          end
        end else begin
          div_num = {{(NB - MCB - FRAC + CALB){1'b0}}, n1_reg, {(FRAC - CALB){1'b0}}};
          div_den = {1'b0, p1_reg};
          state_n = S_FIT_V01;
        end
      end
      S_FIT_V01: if (ACCEL_FIT == 1 && div_done) begin
        v01_n = quotient;
        div_start = 1'b1;
        div_num = {{(NB - MCB - FRAC + CALB){1'b0}}, n2_reg, {(FRAC - CALB){1'b0}}};
        div_den = {1'b0, p2_reg};
        state_n = S_FIT_V12;
      end
      S_FIT_V12: if (ACCEL_FIT == 1 && div_done) begin
        d_n = d;
        state_n = S_FIT_D;
      end
      S_FIT_D: if (ACCEL_FIT == 1) begin
        div_start = 1'b1;
        div_num = {{(NB - QB - 2){1'b0}}, d_abs, 1'b0};
        div_den = p_sum_reg;
        negative_n = negative_reg ^ d_reg[QB];
        state_n = S_FIT_A;
      end
      S_FIT_A: if (ACCEL_FIT == 1 && div_done) begin
        multiplier_n = fit_multiplier << (MB - TB - 1);
        multiplicand_n = accel_fit;
        mul_left_n = TB[5:0] + 6'd1;
        product_n = {PB{1'b0}};
        state_n = S_FIT_MUL;
      end
      S_FIT_MUL: if (ACCEL_FIT == 1 && mul_done) begin
        v_fit_n = v_fit_sum;
        state_n = S_FIT_LOAD;
      end
      S_FIT_LOAD: if (ACCEL_FIT == 1) begin
        velocity_n = v_fit;
        accel_n = multiplicand_reg;
        valid_n = 1'b1;
        if (v_fit_wrong) begin  // decelerated through 0: it stops there
          velocity_n = {VB{1'b0}};
          accel_n = {AB{1'b0}};
        end
        state_n = S_IDLE;
      end
      S_DECAY: if (div_done) begin
        accel_n = negative_reg ? {1'b0, quotient} : -{1'b0, quotient};
        state_n = S_IDLE;
      end
      default: begin
      end
    endcase

    // Overdue: decay to 0 over a third of the time since the step. (Evaluated without
    // waiting for the zero-crossing test: a hold or a stop below overrides it, and the
    // divider's cancel wins over its start.)
    if (idle && !decaying_reg && !step && !illegal && !v_zero && overdue) begin
      negative_n = velocity_reg[VB-1];
      div_start = 1'b1;
      div_num = {{(NB - VB - 1){1'b0}}, {1'b0, v_abs, 1'b0} + {2'b00, v_abs}};
      div_den = {1'b0, since_step_reg};
      state_n = S_DECAY;
      decaying_n = 1'b1;
    end
    // A hold, or a stop: integrating reached 0 (decaying), or no step for
    // 2^TIMER_BITS - 1 clocks.
    if (stop || timeout) begin
      velocity_n = {VB{1'b0}};
      accel_n = {AB{1'b0}};
      valid_n = 1'b1;
      decaying_n = 1'b0;
      have_prev_n = 1'b0;
      last_fit_n = 1'b0;
      step_speed_n = {(VB - 1){1'b0}};
      held_n = 1'b0;
      div_cancel = 1'b1;
      state_n = S_IDLE;
    end else if (hold) begin
      velocity_n = {VB{1'b0}};
      held_n = 1'b1;
      zero_at_n = since_step_reg;
      decaying_n = 1'b0;
      div_cancel = 1'b1;
      state_n = S_IDLE;
    end

    // Events, which win over all the above.
    speed = v_abs;  // |velocity| as the cycle began
    if (illegal) begin
      velocity_n = {VB{1'b0}};
      accel_n = {AB{1'b0}};
      valid_n = 1'b0;
      decaying_n = 1'b0;
      held_n = 1'b0;
      have_a_n = 1'b0;
      have_prev_n = 1'b0;
      last_fit_n = 1'b0;
      moved_n = 1'b0;
      since_step_n = {{(TB - 1){1'b0}}, 1'b1};
      lead_n = {LB{1'b0}};
      div_cancel = 1'b1;
      div_start = 1'b0;
      state_n = S_IDLE;
    end else if (step) begin
      count_n = step_cw ? count_reg + 1'b1 : count_reg - 1'b1;
      cw_n = step_cw;
      moved_n = 1'b1;
      since_step_n = {{(TB - 1){1'b0}}, 1'b1};
      lead_n = {LB{1'b0}};
      // held, decaying and accel as the cycle began (the model's held0, decaying0, accel0)
      if (held_reg && !reversal) begin  // it did not reverse: the acceleration was wrong
        accel_n = {AB{1'b0}};
        have_prev_n = 1'b0;
        last_fit_n = 1'b0;
      end
      held_n = 1'b0;
      if (decaying_reg) begin
        decaying_n = 1'b0;
        accel_n = {AB{1'b0}};
        if (state_n == S_DECAY) begin
          div_cancel = 1'b1;
          div_start = 1'b0;
          state_n = S_IDLE;
        end
      end
      if (reversal) begin
        speed = step_speed_reg;
        velocity_n = step_cw ? {1'b0, step_speed_reg} : -{1'b0, step_speed_reg};
        have_prev_n = 1'b0;
        last_negative_n = !last_negative_reg;  // accel goes on; the speed's trend turns
        have_a_n = 1'b1;
        x_a_n = x;
        c_a_n = step_c;
        since_a_n = {{(TB - 1){1'b0}}, 1'b1};
        div_cancel = 1'b1;
        div_start = 1'b0;
        state_n = S_IDLE;
      end else if (!have_a_reg || since_a_reg == TIMER_MAX) begin
        have_prev_n = 1'b0;
        last_fit_n = 1'b0;
        have_a_n = 1'b1;
        x_a_n = x;
        c_a_n = step_c;
        since_a_n = {{(TB - 1){1'b0}}, 1'b1};
      end else if (idle) begin
        negative_n = !step_cw;
        if (closes && have_prev_n) begin  // _n: a hold let go just now clears it
          n1_n = n_cal;
          p1_n = since_a_reg;
          n2_n = prev_n_reg;
          p2_n = prev_clocks_reg;
          if (ACCEL_FIT == 1) begin
            multiplier_n = n_wide << (MB - MCB);
            multiplicand_n = {{(AB - TB){1'b0}}, prev_clocks_reg};
            mul_left_n = MCB[5:0];
            product_n = {PB{1'b0}};
            state_n = S_CROSS1;
          end else begin
            state_n = S_SUMS;
          end
        end else if ((closes || !have_prev_n) && accel_reg == {AB{1'b0}} && !held_reg) begin
          // The mean since A, unless an acceleration is known (after a reversal): then
          // the velocity integrates it until a fit.
          div_start = 1'b1;
          div_cancel = 1'b0;  // a stop in this cycle does not cancel the new mean
          div_num = {{(NB - MCB - FRAC + CALB){1'b0}}, n_cal, {(FRAC - CALB){1'b0}}};
          div_den = {1'b0, since_a_reg};
          state_n = S_MEAN;
        end
        if (closes) begin
          have_prev_n = 1'b1;
          prev_n_n = n_cal;
          prev_clocks_n = since_a_reg;
          x_a_n = x;
          c_a_n = step_c;
          since_a_n = {{(TB - 1){1'b0}}, 1'b1};
        end
      end
      step_speed_n = speed;
    end

  end

  always @(posedge clk) begin
    if (rst) begin
      velocity_reg <= {VB{1'b0}};
      accel_reg <= {AB{1'b0}};
      valid_reg <= 1'b0;
      count_reg <= {CB{1'b0}};
      cw_reg <= 1'b1;
      moved_reg <= 1'b0;
      step_speed_reg <= {(VB - 1){1'b0}};
      held_reg <= 1'b0;
      zero_at_reg <= {TB{1'b0}};
      since_step_reg <= {TB{1'b0}};
      lead_reg <= {LB{1'b0}};
      have_a_reg <= 1'b0;
      x_a_reg <= {CB{1'b0}};
      c_a_reg <= 16'd0;
      since_a_reg <= {TB{1'b0}};
      have_prev_reg <= 1'b0;
      prev_n_reg <= {MCB{1'b0}};
      prev_clocks_reg <= {TB{1'b0}};
      n1_reg <= {MCB{1'b0}};
      p1_reg <= {TB{1'b0}};
      n2_reg <= {MCB{1'b0}};
      p2_reg <= {TB{1'b0}};
      state_reg <= S_IDLE;
      negative_reg <= 1'b0;
      v01_reg <= {QB{1'b0}};
      cross_reg <= {(XB - 1){1'b0}};
      diff_reg <= {XB{1'b0}};
      n_less_reg <= {(MCB + 1){1'b0}};
      p_sum_reg <= {(TB + 1){1'b0}};
      d_reg <= {(QB + 1){1'b0}};
      v_fit_reg <= {(PB + 1){1'b0}};
      mul_left_reg <= 6'd0;
      multiplier_reg <= {MB{1'b0}};
      multiplicand_reg <= {AB{1'b0}};
      product_reg <= {PB{1'b0}};
      decaying_reg <= 1'b0;
      last_negative_reg <= 1'b0;
      last_fit_reg <= 1'b0;
    end else begin
      velocity_reg <= velocity_n;
      accel_reg <= accel_n;
      valid_reg <= valid_n;
      count_reg <= count_n;
      cw_reg <= cw_n;
      moved_reg <= moved_n;
      step_speed_reg <= step_speed_n;
      held_reg <= held_n;
      zero_at_reg <= zero_at_n;
      since_step_reg <= since_step_n;
      lead_reg <= lead_n;
      have_a_reg <= have_a_n;
      x_a_reg <= x_a_n;
      c_a_reg <= c_a_n;
      since_a_reg <= since_a_n;
      have_prev_reg <= have_prev_n;
      prev_n_reg <= prev_n_n;
      prev_clocks_reg <= prev_clocks_n;
      n1_reg <= n1_n;
      p1_reg <= p1_n;
      n2_reg <= n2_n;
      p2_reg <= p2_n;
      state_reg <= state_n;
      negative_reg <= negative_n;
      v01_reg <= v01_n;
      cross_reg <= cross_n;
      diff_reg <= diff_n;
      n_less_reg <= n_less_n;
      p_sum_reg <= p_sum_n;
      d_reg <= d_n;
      v_fit_reg <= v_fit_n;
      mul_left_reg <= mul_left_n;
      multiplier_reg <= multiplier_n;
      multiplicand_reg <= multiplicand_n;
      product_reg <= product_n;
      decaying_reg <= decaying_n;
      last_negative_reg <= last_negative_n;
      last_fit_reg <= last_fit_n;
    end
  end

  assign velocity = velocity_reg;
  assign accel    = accel_reg;
  assign valid    = valid_reg;

endmodule

`resetall
