// SPDX-License-Identifier: Apache-2.0
// prenc_period: velocity from the period of the sync track's last cycle, for a small
// FPGA (prenc_fine's PERIOD = 1; docs/fine.md). The dVRK firmware's method, and the
// bench's "period" baseline, in integers.
//
// Units: quarters (quadrature states) and clocks; `velocity` is signed with 48
// fractional bits (quarters per clock: prenc_velocity's unit), its lowest 16 bits 0.
//
// - A step is an interval: the clocks since the step before. After four intervals the
//   same way (five steps), the velocity is 4 / (their sum): a full sync cycle, edges of
//   one type, so that the A/B phase and duty errors cancel. Before that (after a
//   reversal, the start) it is 1 / (the last interval). The division (prenc_divider,
//   32 fractional bits) starts 2 clocks after the step and takes DIV_CLOCKS = 35; a
//   step that comes while it runs is taken when it is done (the newest intervals).
// - The sign is the last step's (the magnitude follows with the division).
// - Overdue (no step for 1.5 times the interval the velocity came from): the magnitude
//   is at most 1.5 quarters (a printed disc's widest quarter) over the clocks since the
//   last step, a division started again whenever the divider is free; so a slowing
//   disc's velocity falls as 1 / t. No step for 4 times that interval, or for
//   2^TIMER_BITS - 1 clocks: a stop, 0 (valid). The thresholds are compared a clock
//   ahead and registered (the UP5K's 30 MHz).
// - The first step after reset, a stop or an illegal transition is an anchor: the
//   velocity is valid from the step after. An illegal transition drops it (valid 0).
// Model: prenc.fine.period.Period, which this equals clock for clock.
//
// Latency: a step's velocity shows DIV_CLOCKS + 4 clocks after it (the period's sum,
// the division, the magnitude's register, the output's); its sign 1 clock after it.
//
// Parameters
//   TIMER_BITS   width of the clocks counted, 12..32 (26: 2.2 s at 30 MHz)
//
// Ports
//   step, step_cw, illegal   the quadrature decoder's registered outputs (prenc_core's
//                            sync_step, direction, sync_illegal)
//   velocity     quarters per clock, signed, 48 fractional bits
//   valid        the velocity is an estimate (0 after reset and an illegal transition)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_period #(
  parameter integer TIMER_BITS = 26
) (
  input  wire        clk,
  input  wire        rst,
  input  wire        step,
  input  wire        step_cw,
  input  wire        illegal,
  output wire [50:0] velocity,
  output wire        valid
);

  generate
    if (TIMER_BITS < 12 || TIMER_BITS > 32) begin : g_bad_timer_bits
      initial $display("ERROR: %m: parameter TIMER_BITS = %0d is out of range 12..32", TIMER_BITS);
      prenc_period_parameter_TIMER_BITS_out_of_range_12_to_32 u_stop ();
    end
  endgenerate

  localparam integer TB   = TIMER_BITS;
  localparam integer FP   = 32;          // the quotient's fractional bits
  localparam integer QB   = FP + 1;      // the quotient: below 2 quarters a clock
  localparam integer NB   = FP + 3;      // the numerator: 1 or 4 quarters
  localparam integer DB   = TB + 2;      // the denominator: up to four intervals
  localparam [TB-1:0] TIMER_MAX = {TB{1'b1}};
  localparam [QB-1:0] NO_BOUND  = {QB{1'b1}};

  // Registers (the model's attributes of the same names).
  reg          moved_reg;      // a step since reset, a stop or an illegal transition
  reg          cw_reg;         // the last step's way
  reg [TB-1:0] since_reg;      // clocks since the last step (saturating)
  reg [TB-1:0] q0_reg;         // the last four intervals, newest first
  reg [TB-1:0] q1_reg;
  reg [TB-1:0] q2_reg;
  reg [TB-1:0] q3_reg;
  reg [2:0]    run_reg;        // of them, the same way as the last step (0..4)
  reg [TB:0]   change_reg;     // the newest interval less the one dropped, signed
  reg [DB-1:0] period_reg;     // q0 + q1 + q2 + q3 (a clock after the step)
  reg          summing_reg;    // period_reg takes change_reg this clock
  reg          want_reg;       // a step's division is due
  reg          busy_reg;       // the divider runs
  reg          bounding_reg;   // ... a bound's division
  reg [TB-1:0] interval_reg;   // the interval the velocity came from
  reg [TB:0]   late_reg;       // 1.5 times that: a step later is overdue
  reg          timed_reg;      // the velocity is from this motion's steps
  reg          past_late_reg;  // since_reg > late_reg (compared the clock before)
  reg          past_stop_reg;  // since_reg > 4 interval_reg (likewise)
  reg          timeout_reg;    // since_reg == TIMER_MAX (registered beside it)
  reg [QB-1:0] speed_reg;      // the last step's division
  reg [QB-1:0] bound_reg;      // 1.5 / (clocks since the last step), once overdue
  reg          valid_reg;
  reg [QB-1:0] shown_reg;      // min(speed, bound), registered
  reg signed [50:0] velocity_reg;   // with the sign: the output, a clock later

  // The divider.
  wire          div_done;
  wire [QB-1:0] quotient;
  wire          full = (run_reg == 3'd4);
  wire          start_step  = want_reg && !busy_reg;
  wire          overdue     = moved_reg && timed_reg && past_late_reg;
  wire          start_bound = !want_reg && !busy_reg && overdue && !step;   // (never the
                                                                     // clock after a step)
  wire [NB-1:0] div_num = !start_step ? {3'b001, 1'b1, {(FP - 1){1'b0}}}   // 1.5 (a bound)
                        : full ? {3'b100, {FP{1'b0}}} : {3'b001, {FP{1'b0}}};
  wire [DB-1:0] div_den = !start_step ? {2'b00, since_reg} : full ? period_reg : {2'b00, q0_reg};
  wire          stop = moved_reg && (timeout_reg || (timed_reg && past_stop_reg));
  wire          div_cancel = illegal || stop || (step && busy_reg && bounding_reg);

  prenc_divider #(
    .NUM_BITS      (NB),
    .DEN_BITS      (DB),
    .QUOTIENT_BITS (QB)
  ) u_divider (
    .clk      (clk),
    .rst      (rst),
    .start    (start_step || start_bound),
    .cancel   (div_cancel),
    .num      (div_num),
    .den      (div_den),
    .done     (div_done),
    .quotient (quotient)
  );

  wire signed [50:0] magnitude = {2'b00, shown_reg, 16'd0};
  wire [TB-1:0] interval = full ? period_reg[TB+1:2] : q0_reg;
  wire [QB-1:0] shown = (bound_reg < speed_reg) ? bound_reg : speed_reg;

  always @(posedge clk) begin
    if (!timeout_reg) since_reg <= since_reg + 1'b1;
    timeout_reg <= !step && !illegal && (since_reg >= TIMER_MAX - 1'b1);
    // The thresholds, compared a clock ahead (since_reg + 1 > x: since_reg >= x), unless
    // since_reg or they change now.
    past_late_reg <= !step && !start_step && ({1'b0, since_reg} >= late_reg);
    past_stop_reg <= !step && !start_step && ({2'b00, since_reg} >= {interval_reg, 2'b00});
    summing_reg <= 1'b0;
    if (summing_reg) begin
      period_reg <= period_reg + {{(DB - TB - 1){change_reg[TB]}}, change_reg};
      want_reg   <= 1'b1;
    end
    if (start_step) begin
      want_reg     <= 1'b0;
      busy_reg     <= 1'b1;
      bounding_reg <= 1'b0;
      interval_reg <= interval;
      late_reg     <= {1'b0, interval} + {2'b00, interval[TB-1:1]};
    end else if (start_bound) begin
      busy_reg     <= 1'b1;
      bounding_reg <= 1'b1;
    end
    if (div_done && busy_reg) begin   // (a division cancelled may still say done)
      busy_reg <= 1'b0;
      if (bounding_reg) begin
        bound_reg <= quotient;
      end else begin
        speed_reg <= quotient;
        valid_reg <= 1'b1;
        timed_reg <= 1'b1;
      end
    end
    shown_reg <= shown;
    velocity_reg <= cw_reg ? magnitude : -magnitude;

    // Events, which win over all the above.
    if (illegal || stop) begin
      moved_reg  <= 1'b0;
      timed_reg  <= 1'b0;
      run_reg    <= 3'd0;
      want_reg   <= 1'b0;
      busy_reg   <= 1'b0;
      speed_reg  <= {QB{1'b0}};
      bound_reg  <= NO_BOUND;
      shown_reg  <= {QB{1'b0}};
      q0_reg     <= {TB{1'b0}};
      q1_reg     <= {TB{1'b0}};
      q2_reg     <= {TB{1'b0}};
      q3_reg     <= {TB{1'b0}};
      period_reg <= {DB{1'b0}};
      summing_reg <= 1'b0;
      valid_reg  <= !illegal;
      if (illegal) since_reg <= {{(TB - 1){1'b0}}, 1'b1};
    end else if (step) begin
      moved_reg <= 1'b1;
      cw_reg    <= step_cw;
      since_reg <= {{(TB - 1){1'b0}}, 1'b1};
      bound_reg <= NO_BOUND;
      if (busy_reg && bounding_reg) busy_reg <= 1'b0;   // cancelled
      if (moved_reg) begin
        run_reg     <= (step_cw != cw_reg) ? 3'd0 : full ? 3'd4 : run_reg + 3'd1;
        q0_reg      <= since_reg;
        q1_reg      <= q0_reg;
        q2_reg      <= q1_reg;
        q3_reg      <= q2_reg;
        change_reg  <= {1'b0, since_reg} - {1'b0, q3_reg};
        summing_reg <= 1'b1;
      end
    end

    if (rst) begin
      moved_reg    <= 1'b0;
      cw_reg       <= 1'b1;
      since_reg    <= {TB{1'b0}};
      timeout_reg  <= 1'b0;
      q0_reg       <= {TB{1'b0}};
      q1_reg       <= {TB{1'b0}};
      q2_reg       <= {TB{1'b0}};
      q3_reg       <= {TB{1'b0}};
      run_reg      <= 3'd0;
      change_reg   <= {(TB + 1){1'b0}};
      period_reg   <= {DB{1'b0}};
      summing_reg  <= 1'b0;
      want_reg     <= 1'b0;
      busy_reg     <= 1'b0;
      bounding_reg <= 1'b0;
      interval_reg <= {TB{1'b0}};
      late_reg     <= {(TB + 1){1'b0}};
      timed_reg    <= 1'b0;
      past_late_reg <= 1'b0;
      past_stop_reg <= 1'b0;
      speed_reg    <= {QB{1'b0}};
      bound_reg    <= NO_BOUND;
      valid_reg    <= 1'b0;
      shown_reg    <= {QB{1'b0}};
      velocity_reg <= 51'd0;
    end
  end

  assign velocity = velocity_reg;
  assign valid    = valid_reg;

endmodule

`resetall
