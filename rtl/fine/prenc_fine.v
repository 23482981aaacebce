// SPDX-License-Identifier: Apache-2.0
// prenc_fine: fine position and velocity beside the core (docs/fine.md).
//
//   prenc_core: sync_step, direction, sync_illegal -> prenc_velocity -> velocity, accel
//                                  (TRACKER = 1, 2: prenc_tracker; PERIOD = 1: prenc_period)
//               pos_hyb, pos_valid ------------------> prenc_fine_position -> fine_pos
//
// The core stays the judge of the position: fine_pos's quarter is pos_hyb's while
// pos_valid, but for the extrapolation over the pipeline (LOOKAHEAD_HALVES), which can
// carry it past the quarter's edge by |velocity| * LOOKAHEAD_HALVES / 2 quarters.
//
// With CAL = 1, the calibration table (rtl/cal/prenc_cal_lookup.v, docs/calibration.md)
// gives both blocks the true places of their quarters' edges:
// - the decoder's quarter, pos_hyb plus the steps pos_hyb does not show yet (this
//   cycle's and the three before: pos_hyb follows the decoder by 4 clocks), goes to
//   the table, which gives c[q] and c[q + 1] one clock later, registered once more
//   (the block RAM's output is slow);
// - so prenc_velocity (or prenc_tracker) takes the decoder's step, direction and
//   illegal transition two clocks late, with those corrections, and
//   prenc_fine_position takes them 2 clocks later again, when pos_hyb shows that
//   quarter;
// - the corrections count only while the table holds both words and pos_valid held
//   when the quarter was asked (else 0: the nominal edges).
// Model: prenc.fine.fine.Fine.
//
// Latency: fine_pos is OUTPUT_DELAY = 3 clocks after the core's pos_hyb (extrapolated
// over the clocks from the pins by LOOKAHEAD_HALVES); the velocity updates FULL_CLOCKS
// after a window closes and integrates its acceleration every clock in between
// (prenc_velocity); with TRACKER = 1 or 2 an edge's update lands 32 clocks after it,
// compensated to its instant, and the output is registered (prenc_tracker).
//
// Parameters
//   N, FINE_BITS, LOOKAHEAD_HALVES   prenc_fine_position's (N 2..24, F 0..8, 0..255)
//   WINDOW, TIMER_BITS, QUARTER_WINDOWS, ACCEL_FIT   prenc_velocity's (2048, 26, 0, 1)
//   TRACKER    1: the velocity from prenc_tracker instead (a tracking filter with a gain
//              table: GAIN_FILE, from `python -m prenc gains`; TIMER_BITS is its too,
//              WINDOW, QUARTER_WINDOWS, ACCEL_FIT unused; with CAL = 1 it takes the
//              table's corrections as prenc_velocity does); 0: prenc_velocity (default)
//              2: prenc_tracker, and between edges the fine position is the tracker's
//              filtered position (for a disc whose edges are off by more than a clock
//              or two, printed and not calibrated: it averages the edges' errors;
//              docs/fine.md); 1 and 0: the last edge and the velocity
//   GAIN_FILE  with TRACKER = 1 or 2: the gain table ($readmemh)
//   PERIOD     1: the velocity from prenc_period instead, the period of the sync track's
//              last cycle (the dVRK firmware's method: about a tenth of prenc_velocity's
//              logic, for a small FPGA such as the iCEBreaker's UP5K; accel 0; needs
//              TRACKER = 0 and CAL = 0; TIMER_BITS is its); 0: not (default)
//   ENABLE     1: the blocks are built (default); 0: not (a device with no room for
//              them): fine_pos is pos_hyb (FINE_BITS must be 0), the velocity 0, not valid
//   CAL        1: with the calibration table (N 2..16); 0: without (default)
//   CAL_FILE   with CAL = 1: the table's file ($readmemh, prenc.cal.table's format);
//              "" : all zero until written
//
// Ports: as prenc_velocity's and prenc_fine_position's, and
//   velocity_word   the velocity in quarters per clock x 2^32, signed, saturated to 32 bits
//                   (the Wishbone register's and the host link's unit)
//   cal_write, cal_address, cal_data   with CAL = 1: a word of the table written (c[x],
//                   two's complement, 2^-12 quarter); it counts from the next clock
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_fine #(
  parameter integer N                = 10,
  parameter integer FINE_BITS        = 8,
  parameter integer LOOKAHEAD_HALVES = 0,
  parameter integer WINDOW           = 2048,
  parameter integer TIMER_BITS       = 26,
  parameter integer QUARTER_WINDOWS  = 0,
  parameter integer ACCEL_FIT        = 1,
  parameter integer TRACKER          = 0,
  parameter         GAIN_FILE        = "prenc_gains_n10_30mhz.hex",
  parameter integer PERIOD           = 0,
  parameter integer ENABLE           = 1,
  parameter integer CAL              = 0,
  parameter         CAL_FILE         = ""
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire [N+1:0]           pos_hyb,
  input  wire                   pos_valid,
  input  wire                   step,
  input  wire                   step_cw,
  input  wire                   illegal,
  input  wire                   cal_write,
  input  wire [N+1:0]           cal_address,
  input  wire [15:0]            cal_data,
  output wire [N+FINE_BITS+1:0] fine_pos,
  output wire                   fine_valid,
  output wire                   interpolated,
  output wire [50:0]            velocity,
  output wire [49:0]            accel,
  output wire                   velocity_valid,
  output wire [31:0]            velocity_word
);

  // The velocity's top 35 bits (48 - 16 fractional bits), saturated to 32.
  wire v_fits = (velocity[50:47] == 4'b0000) || (velocity[50:47] == 4'b1111);
  assign velocity_word = v_fits ? velocity[47:16] : {velocity[50], {31{~velocity[50]}}};
  wire unused_ok = &{1'b0, velocity[15:0]};

  generate
    if (ENABLE != 0 && ENABLE != 1) begin : g_bad_enable
      initial $display("ERROR: %m: parameter ENABLE = %0d must be 0 or 1", ENABLE);
      prenc_fine_parameter_ENABLE_must_be_0_or_1 u_stop ();
    end
    if (ENABLE == 0 && FINE_BITS != 0) begin : g_bad_fine_bits
      initial $display("ERROR: %m: parameter FINE_BITS = %0d needs ENABLE = 1", FINE_BITS);
      prenc_fine_parameter_FINE_BITS_needs_ENABLE_1 u_stop ();
    end
    if (TRACKER < 0 || TRACKER > 2) begin : g_bad_tracker
      initial $display("ERROR: %m: parameter TRACKER = %0d is out of range 0..2", TRACKER);
      prenc_fine_parameter_TRACKER_out_of_range_0_to_2 u_stop ();
    end
    if (TRACKER != 0 && ENABLE != 1) begin : g_bad_tracker_enable
      initial $display("ERROR: %m: parameter TRACKER = %0d needs ENABLE = 1", TRACKER);
      prenc_fine_parameter_TRACKER_needs_ENABLE_1 u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_fine_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (CAL == 1 && ENABLE == 0) begin : g_bad_cal_enable
      initial $display("ERROR: %m: parameter CAL = 1 needs ENABLE = 1");
      prenc_fine_parameter_CAL_needs_ENABLE_1 u_stop ();
    end
    if (PERIOD != 0 && PERIOD != 1) begin : g_bad_period
      initial $display("ERROR: %m: parameter PERIOD = %0d must be 0 or 1", PERIOD);
      prenc_fine_parameter_PERIOD_must_be_0_or_1 u_stop ();
    end
    if (PERIOD == 1 && (ENABLE != 1 || TRACKER != 0 || CAL != 0)) begin : g_bad_period_with
      initial $display("ERROR: %m: parameter PERIOD = 1 needs ENABLE = 1, TRACKER = 0, CAL = 0");
      prenc_fine_parameter_PERIOD_needs_ENABLE_1_TRACKER_0_CAL_0 u_stop ();
    end
  endgenerate

  generate
    if (ENABLE == 1) begin : g_fine
      // The velocity's inputs, and the corrections of the velocity's and the fine
      // position's quarters (without CAL: the decoder's outputs as they are, and 0).
      wire        v_step;
      wire        v_step_cw;
      wire        v_illegal;
      wire [15:0] v_c_lo;
      wire [15:0] v_c_hi;
      wire [15:0] f_c_lo;
      wire [15:0] f_c_hi;

      if (CAL == 1) begin : g_cal
        reg          late_step_0_reg;    // the decoder's outputs, one and two clocks late
        reg          late_cw_0_reg;
        reg          late_illegal_0_reg;
        reg          late_valid_0_reg;
        reg          late_step_1_reg;
        reg          late_cw_1_reg;
        reg          late_illegal_1_reg;
        reg  [15:0]  c_lo_reg;           // the table's answer, registered (gated)
        reg  [15:0]  c_hi_reg;
        reg  [15:0]  pos_lo_0_reg;       // the corrections on their way to the fine
        reg  [15:0]  pos_hi_0_reg;       // position (registers, not arrays: Yosys would
        reg  [15:0]  pos_lo_1_reg;       // read arrays as memories)
        reg  [15:0]  pos_hi_1_reg;
        wire [N+1:0] quarter;

        prenc_decoder_quarter #(
          .N (N)
        ) u_quarter (
          .clk     (clk),
          .rst     (rst),
          .pos_hyb (pos_hyb),
          .step    (step),
          .step_cw (step_cw),
          .quarter (quarter)
        );

        wire [15:0]  c_lo;
        wire [15:0]  c_hi;
        wire         c_ok;
        wire         used = c_ok & late_valid_0_reg;

        prenc_cal_lookup #(
          .N        (N),
          .CAL_FILE (CAL_FILE)
        ) u_lookup (
          .clk     (clk),
          .rst     (rst),
          .quarter (quarter),
          .write   (cal_write),
          .address (cal_address),
          .data    (cal_data),
          .c_lo    (c_lo),
          .c_hi    (c_hi),
          .ok      (c_ok)
        );

        always @(posedge clk) begin
          late_step_0_reg    <= step;
          late_cw_0_reg      <= step_cw;
          late_illegal_0_reg <= illegal;
          late_valid_0_reg   <= pos_valid;
          late_step_1_reg    <= late_step_0_reg;
          late_cw_1_reg      <= late_cw_0_reg;
          late_illegal_1_reg <= late_illegal_0_reg;
          c_lo_reg           <= used ? c_lo : 16'd0;
          c_hi_reg           <= used ? c_hi : 16'd0;
          pos_lo_0_reg       <= c_lo_reg;
          pos_hi_0_reg       <= c_hi_reg;
          pos_lo_1_reg       <= pos_lo_0_reg;
          pos_hi_1_reg       <= pos_hi_0_reg;
          if (rst) begin
            late_step_0_reg    <= 1'b0;
            late_cw_0_reg      <= 1'b1;
            late_illegal_0_reg <= 1'b0;
            late_valid_0_reg   <= 1'b0;
            late_step_1_reg    <= 1'b0;
            late_cw_1_reg      <= 1'b1;
            late_illegal_1_reg <= 1'b0;
            c_lo_reg           <= 16'd0;
            c_hi_reg           <= 16'd0;
            pos_lo_0_reg       <= 16'd0;
            pos_hi_0_reg       <= 16'd0;
            pos_lo_1_reg       <= 16'd0;
            pos_hi_1_reg       <= 16'd0;
          end
        end

        assign v_step    = late_step_1_reg;
        assign v_step_cw = late_cw_1_reg;
        assign v_illegal = late_illegal_1_reg;
        assign v_c_lo    = c_lo_reg;
        assign v_c_hi    = c_hi_reg;
        assign f_c_lo    = pos_lo_1_reg;
        assign f_c_hi    = pos_hi_1_reg;
      end else begin : g_nominal
        assign v_step    = step;
        assign v_step_cw = step_cw;
        assign v_illegal = illegal;
        assign v_c_lo    = 16'd0;
        assign v_c_hi    = 16'd0;
        assign f_c_lo    = 16'd0;
        assign f_c_hi    = 16'd0;
        wire unused_cal = &{1'b0, cal_write, cal_address, cal_data};
      end

      wire [27:0] offset;         // the tracker's filtered position (TRACKER = 2)
      wire        offset_valid;

      if (TRACKER != 0) begin : g_tracker
        wire [27:0] t_offset;
        wire        t_offset_valid;

        prenc_tracker #(
          .TIMER_BITS (TIMER_BITS),
          .GAIN_FILE  (GAIN_FILE),
          .CAL        (CAL)
        ) u_tracker (
          .clk      (clk),
          .rst      (rst),
          .step     (v_step),
          .step_cw  (v_step_cw),
          .illegal  (v_illegal),
          .c_lo     (v_c_lo),
          .c_hi     (v_c_hi),
          .velocity (velocity),
          .accel    (accel),
          .valid    (velocity_valid),
          .offset       (t_offset),
          .offset_valid (t_offset_valid)
        );

        if (TRACKER == 2 && CAL == 0) begin : g_offset_delay
          // To meet the step prenc_fine_position takes (3 clocks old; the tracker's
          // registers hold it from 1 clock after): 2 registers. With CAL = 1 the
          // tracker takes the step 2 clocks late already.
          reg [27:0] offset_0_reg;
          reg [27:0] offset_1_reg;
          reg        offset_valid_0_reg;
          reg        offset_valid_1_reg;
          always @(posedge clk) begin
            offset_0_reg       <= t_offset;
            offset_1_reg       <= offset_0_reg;
            offset_valid_0_reg <= t_offset_valid;
            offset_valid_1_reg <= offset_valid_0_reg;
            if (rst) begin
              offset_0_reg       <= 28'd0;
              offset_1_reg       <= 28'd0;
              offset_valid_0_reg <= 1'b0;
              offset_valid_1_reg <= 1'b0;
            end
          end
          assign offset       = offset_1_reg;
          assign offset_valid = offset_valid_1_reg;
        end else if (TRACKER == 2) begin : g_offset
          assign offset       = t_offset;
          assign offset_valid = t_offset_valid;
        end else begin : g_no_offset
          assign offset       = 28'd0;
          assign offset_valid = 1'b0;
          wire unused_offset = &{1'b0, t_offset, t_offset_valid};
        end
      end else if (PERIOD == 1) begin : g_period
        prenc_period #(
          .TIMER_BITS (TIMER_BITS)
        ) u_period (
          .clk      (clk),
          .rst      (rst),
          .step     (v_step),
          .step_cw  (v_step_cw),
          .illegal  (v_illegal),
          .velocity (velocity),
          .valid    (velocity_valid)
        );
        assign accel        = 50'd0;
        assign offset       = 28'd0;
        assign offset_valid = 1'b0;
        wire unused_period = &{1'b0, v_c_lo, v_c_hi};
      end else begin : g_velocity
        prenc_velocity #(
          .WINDOW     (WINDOW),
          .TIMER_BITS (TIMER_BITS),
          .CAL        (CAL),
          .QUARTER_WINDOWS (QUARTER_WINDOWS),
          .ACCEL_FIT  (ACCEL_FIT)
        ) u_velocity (
          .clk      (clk),
          .rst      (rst),
          .step     (v_step),
          .step_cw  (v_step_cw),
          .illegal  (v_illegal),
          .c_lo     (v_c_lo),
          .c_hi     (v_c_hi),
          .velocity (velocity),
          .accel    (accel),
          .valid    (velocity_valid)
        );
        assign offset       = 28'd0;
        assign offset_valid = 1'b0;
      end

      prenc_fine_position #(
        .N                (N),
        .FINE_BITS        (FINE_BITS),
        .LOOKAHEAD_HALVES (LOOKAHEAD_HALVES),
        .CAL              (CAL)
      ) u_fine_position (
        .clk            (clk),
        .rst            (rst),
        .pos_hyb        (pos_hyb),
        .pos_valid      (pos_valid),
        .step           (step),
        .step_cw        (step_cw),
        .velocity       (velocity),
        .velocity_valid (velocity_valid),
        .c_lo           (f_c_lo),
        .c_hi           (f_c_hi),
        .offset         (offset),
        .offset_valid   (offset_valid),
        .fine_pos       (fine_pos),
        .fine_valid     (fine_valid),
        .interpolated   (interpolated)
      );
    end else begin : g_none
      assign velocity       = 51'd0;
      assign accel          = 50'd0;
      assign velocity_valid = 1'b0;
      assign fine_pos       = pos_hyb;  // FINE_BITS = 0 (checked above)
      assign fine_valid     = pos_valid;
      assign interpolated   = 1'b0;
      wire unused_none = &{1'b0, clk, rst, step, step_cw, illegal, cal_write, cal_address,
                           cal_data};
    end
  endgenerate

endmodule

`resetall
