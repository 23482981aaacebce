// SPDX-License-Identifier: Apache-2.0
// prenc_fine: fine position and velocity beside the core (docs/fine.md).
//
//   prenc_core: sync_step, direction, sync_illegal -> prenc_velocity -> velocity
//               pos_hyb, pos_valid ------------------> prenc_fine_position -> fine_pos
//
// The core stays the judge of the position: fine_pos's quarter is pos_hyb's while
// pos_valid, but for the extrapolation over the pipeline (LOOKAHEAD_HALVES), which can
// carry it past the quarter's edge by |velocity| * LOOKAHEAD_HALVES / 2 quarters.
//
// With CAL = 1, the calibration table (rtl/cal/prenc_cal_lookup.v, docs/calibration.md)
// gives both blocks the true places of their quarters' edges: the table is asked for
// pos_hyb's quarter; its pair (c[q], c[q + 1]) comes READ_DELAY = 3 clocks later and is
// registered, gated (0: the nominal edges, when the pair is not that quarter's, or
// pos_valid was 0). So prenc_fine_position takes pos_hyb, pos_valid and the decoder's
// step CAL_DELAY = 4 clocks late, and prenc_velocity the decoder's step, direction and
// illegal transition VEL_DELAY = 8 clocks late (pos_hyb follows the decoder by 4), each
// with the corrections of its quarter. A disc that steps more often than every 3
// clocks (about 10^7 quarters a second at 30 MHz) gets the nominal edges for some
// quarters.
// Model: prenc.fine.fine.Fine.
//
// Latency: fine_pos is OUTPUT_DELAY clocks after the core's pos_hyb, 3 (7 with CAL = 1),
// extrapolated by LOOKAHEAD_HALVES half clocks (the pins to the output: the board's
// 2 (7 + FILTER + OUTPUT_DELAY)); a fitted velocity is loaded 256 clocks after the step
// that closed its window (VEL_DELAY = 8 more with CAL = 1), extrapolated to that clock
// (prenc_velocity).
//
// Parameters
//   N, FINE_BITS, LOOKAHEAD_HALVES   prenc_fine_position's (N 2..24, F 0..8, 0..255)
//   WINDOW     prenc_velocity's window, clocks (1024 at 30 MHz)
//   ENABLE     1: the blocks are built (default); 0: not (a device with no room for
//              them): fine_pos is pos_hyb (FINE_BITS must be 0), the velocity 0, not valid
//   CAL        1: with the calibration table (N 2..16); 0: without (default)
//   CAL_FILE   with CAL = 1: the table's file ($readmemh, prenc.cal.table's format);
//              "" : all zero until written
//   EDGE_TOLERANCE   how far the edges may be off their places (nominal, or the
//              table's), 1/1000 slot (prenc_velocity's; 0: exact; docs/fine.md); above 0
//              the fine position's phase is a running mean of the edges' (PHASE_FILTER)
//
// Ports: as prenc_velocity's and prenc_fine_position's, and
//   velocity   quarters per clock x 2^32, signed (the Wishbone register's and the host
//              link's unit)
//   cal_write, cal_address, cal_data   with CAL = 1: a word of the table written (c[x],
//              two's complement, 2^-12 quarter); it counts from the next clock
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_fine #(
  parameter integer N                = 10,
  parameter integer FINE_BITS        = 8,
  parameter integer LOOKAHEAD_HALVES = 0,
  parameter integer WINDOW           = 1024,
  parameter integer ENABLE           = 1,
  parameter integer CAL              = 0,
  parameter         CAL_FILE         = "",
  parameter integer EDGE_TOLERANCE   = 0
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
  output wire [31:0]            velocity,
  output wire                   velocity_valid
);

  generate
    if (ENABLE != 0 && ENABLE != 1) begin : g_bad_enable
      initial $display("ERROR: %m: parameter ENABLE = %0d must be 0 or 1", ENABLE);
      prenc_fine_parameter_ENABLE_must_be_0_or_1 u_stop ();
    end
    if (ENABLE == 0 && FINE_BITS != 0) begin : g_bad_fine_bits
      initial $display("ERROR: %m: parameter FINE_BITS = %0d needs ENABLE = 1", FINE_BITS);
      prenc_fine_parameter_FINE_BITS_needs_ENABLE_1 u_stop ();
    end
    if (CAL != 0 && CAL != 1) begin : g_bad_cal
      initial $display("ERROR: %m: parameter CAL = %0d must be 0 or 1", CAL);
      prenc_fine_parameter_CAL_must_be_0_or_1 u_stop ();
    end
    if (CAL == 1 && ENABLE == 0) begin : g_bad_cal_enable
      initial $display("ERROR: %m: parameter CAL = 1 needs ENABLE = 1");
      prenc_fine_parameter_CAL_needs_ENABLE_1 u_stop ();
    end
  endgenerate

  // The pipeline's alignment (docs/fine.md, its timing diagram). pos_hyb follows the
  // decoder's step by POS_LAG clocks (prenc_core); with CAL = 1 the table's pair of a
  // quarter comes READ_DELAY clocks after pos_hyb shows it (prenc_cal_lookup), and one
  // more register gates it: the fine position takes pos_hyb and the decoder's step
  // CAL_DELAY clocks late, the velocity the step VEL_DELAY clocks late, each with the
  // corrections of its quarter.
  localparam integer POS_LAG    = 4;
  localparam integer READ_DELAY = 3;
  localparam integer CAL_DELAY  = READ_DELAY + 1;
  localparam integer VEL_DELAY  = POS_LAG + CAL_DELAY;

  generate
    if (ENABLE == 1) begin : g_fine
      // The velocity's inputs, and the corrections of the velocity's and the fine
      // position's quarters (without CAL: the decoder's outputs as they are, and 0).
      wire        v_step;
      wire        v_step_cw;
      wire        v_illegal;
      wire [15:0] v_c_lo;
      wire [15:0] v_c_hi;
      wire [N+1:0] f_pos_hyb;    // the fine position's inputs
      wire        f_pos_valid;
      wire        f_step;
      wire        f_step_cw;
      wire [15:0] f_c_lo;
      wire [15:0] f_c_hi;

      if (CAL == 1) begin : g_cal
        // The table's pair for pos_hyb, gated and registered: c_reg holds the
        // corrections of pos_hyb of CAL_DELAY clocks before (0 when the lookup has not
        // got them, or pos_valid was 0).
        reg  [CAL_DELAY*(N+2)-1:0] pos_d_reg;     // pos_hyb, pos_valid, the decoder's
        reg  [CAL_DELAY-1:0]       valid_d_reg;   // outputs, CAL_DELAY clocks late for
        reg  [VEL_DELAY-1:0]       step_d_reg;    // the fine position, VEL_DELAY for
        reg  [VEL_DELAY-1:0]       cw_d_reg;      // the velocity
        reg  [VEL_DELAY-1:0]       illegal_d_reg;
        reg  [15:0]                c_lo_reg;
        reg  [15:0]                c_hi_reg;
        wire [15:0]                c_lo;
        wire [15:0]                c_hi;
        wire [N+1:0]               pair_quarter;
        wire                       c_ok;
        wire [N+1:0]               pos_3 = pos_d_reg[3*(N+2)-1:2*(N+2)];
        wire                       used  = c_ok && (pair_quarter == pos_3) && valid_d_reg[2];

        prenc_cal_lookup #(
          .N        (N),
          .CAL_FILE (CAL_FILE)
        ) u_lookup (
          .clk          (clk),
          .rst          (rst),
          .quarter      (pos_hyb),
          .write        (cal_write),
          .address      (cal_address),
          .data         (cal_data),
          .c_lo         (c_lo),
          .c_hi         (c_hi),
          .pair_quarter (pair_quarter),
          .ok           (c_ok)
        );

        always @(posedge clk) begin
          pos_d_reg     <= {pos_d_reg[(CAL_DELAY-1)*(N+2)-1:0], pos_hyb};
          valid_d_reg   <= {valid_d_reg[CAL_DELAY-2:0], pos_valid};
          step_d_reg    <= {step_d_reg[VEL_DELAY-2:0], step};
          cw_d_reg      <= {cw_d_reg[VEL_DELAY-2:0], step_cw};
          illegal_d_reg <= {illegal_d_reg[VEL_DELAY-2:0], illegal};
          c_lo_reg      <= c_lo;
          c_hi_reg      <= c_hi;
          if (rst || !used) begin
            c_lo_reg <= 16'd0;
            c_hi_reg <= 16'd0;
          end
          if (rst) begin
            pos_d_reg     <= {(CAL_DELAY * (N + 2)){1'b0}};
            valid_d_reg   <= {CAL_DELAY{1'b0}};
            step_d_reg    <= {VEL_DELAY{1'b0}};
            cw_d_reg      <= {VEL_DELAY{1'b1}};
            illegal_d_reg <= {VEL_DELAY{1'b0}};
          end
        end

        assign v_step      = step_d_reg[VEL_DELAY-1];
        assign v_step_cw   = cw_d_reg[VEL_DELAY-1];
        assign v_illegal   = illegal_d_reg[VEL_DELAY-1];
        assign v_c_lo      = c_lo_reg;
        assign v_c_hi      = c_hi_reg;
        assign f_pos_hyb   = pos_d_reg[CAL_DELAY*(N+2)-1:(CAL_DELAY-1)*(N+2)];
        assign f_pos_valid = valid_d_reg[CAL_DELAY-1];
        assign f_step      = step_d_reg[CAL_DELAY-1];
        assign f_step_cw   = cw_d_reg[CAL_DELAY-1];
        assign f_c_lo      = c_lo_reg;
        assign f_c_hi      = c_hi_reg;
      end else begin : g_nominal
        assign v_step      = step;
        assign v_step_cw   = step_cw;
        assign v_illegal   = illegal;
        assign v_c_lo      = 16'd0;
        assign v_c_hi      = 16'd0;
        assign f_pos_hyb   = pos_hyb;
        assign f_pos_valid = pos_valid;
        assign f_step      = step;
        assign f_step_cw   = step_cw;
        assign f_c_lo      = 16'd0;
        assign f_c_hi      = 16'd0;
        wire unused_cal = &{1'b0, cal_write, cal_address, cal_data};
      end

      prenc_velocity #(
        .WINDOW         (WINDOW),
        .CAL            (CAL),
        .EDGE_TOLERANCE (EDGE_TOLERANCE)
      ) u_velocity (
        .clk      (clk),
        .rst      (rst),
        .step     (v_step),
        .step_cw  (v_step_cw),
        .illegal  (v_illegal),
        .c_lo     (v_c_lo),
        .c_hi     (v_c_hi),
        .velocity (velocity),
        .valid    (velocity_valid)
      );

      prenc_fine_position #(
        .N                (N),
        .FINE_BITS        (FINE_BITS),
        .LOOKAHEAD_HALVES (LOOKAHEAD_HALVES),
        .CAL              (CAL),
        .PHASE_FILTER     ((EDGE_TOLERANCE > 0) ? 1 : 0)
      ) u_fine_position (
        .clk            (clk),
        .rst            (rst),
        .pos_hyb        (f_pos_hyb),
        .pos_valid      (f_pos_valid),
        .step           (f_step),
        .step_cw        (f_step_cw),
        .velocity       (velocity),
        .velocity_valid (velocity_valid),
        .c_lo           (f_c_lo),
        .c_hi           (f_c_hi),
        .fine_pos       (fine_pos),
        .fine_valid     (fine_valid),
        .interpolated   (interpolated)
      );
    end else begin : g_none
      assign velocity       = 32'd0;
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
