// SPDX-License-Identifier: Apache-2.0
// prenc_fine: fine position and velocity beside the core (docs/fine.md).
//
//   prenc_core: sync_step, direction, sync_illegal -> prenc_velocity -> velocity, accel
//               pos_hyb, pos_valid ------------------> prenc_fine_position -> fine_pos
//
// The core stays the judge of the position: fine_pos's quarter is pos_hyb's while
// pos_valid, but for the extrapolation over the pipeline (LOOKAHEAD_HALVES), which can
// carry it past the quarter's edge by |velocity| * LOOKAHEAD_HALVES / 2 quarters.
//
// Parameters
//   N, FINE_BITS, LOOKAHEAD_HALVES   prenc_fine_position's (N 2..24, F 0..8, 0..255)
//   WINDOW, TIMER_BITS               prenc_velocity's (2048, 26)
//   ENABLE     1: the blocks are built (default); 0: not (a device with no room for
//              them): fine_pos is pos_hyb (FINE_BITS must be 0), the velocity 0, not valid
//
// Ports: as prenc_velocity's and prenc_fine_position's, and
//   velocity_word   the velocity in quarters per clock x 2^32, signed, saturated to 32 bits
//                   (the Wishbone register's and the host link's unit)
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_fine #(
  parameter integer N                = 10,
  parameter integer FINE_BITS        = 8,
  parameter integer LOOKAHEAD_HALVES = 0,
  parameter integer WINDOW           = 2048,
  parameter integer TIMER_BITS       = 26,
  parameter integer ENABLE           = 1
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire [N+1:0]           pos_hyb,
  input  wire                   pos_valid,
  input  wire                   step,
  input  wire                   step_cw,
  input  wire                   illegal,
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
  endgenerate

  generate
    if (ENABLE == 1) begin : g_fine
      prenc_velocity #(
        .WINDOW     (WINDOW),
        .TIMER_BITS (TIMER_BITS)
      ) u_velocity (
        .clk      (clk),
        .rst      (rst),
        .step     (step),
        .step_cw  (step_cw),
        .illegal  (illegal),
        .velocity (velocity),
        .accel    (accel),
        .valid    (velocity_valid)
      );

      prenc_fine_position #(
        .N                (N),
        .FINE_BITS        (FINE_BITS),
        .LOOKAHEAD_HALVES (LOOKAHEAD_HALVES)
      ) u_fine_position (
        .clk            (clk),
        .rst            (rst),
        .pos_hyb        (pos_hyb),
        .pos_valid      (pos_valid),
        .step           (step),
        .step_cw        (step_cw),
        .velocity       (velocity),
        .velocity_valid (velocity_valid),
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
      wire unused_none = &{1'b0, clk, rst, step, step_cw, illegal};
    end
  endgenerate

endmodule

`resetall
