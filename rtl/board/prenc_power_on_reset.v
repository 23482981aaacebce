// SPDX-License-Identifier: Apache-2.0
// prenc_power_on_reset: the board tops' reset, synchronous to the PLL's clock.
//
// `rst` is high from configuration until the PLL has locked and the reset button has
// been released for HOLD clocks, and again whenever the lock is lost or the button is
// pressed. The button passes a two-flop synchronizer. The registers start from their
// initial values, which FPGAs load at configuration; this is the one module that
// relies on them, because nothing can reset the reset.
//
// Latency: rst rises on the clock after the PLL loses lock, or 3 clocks after the
// button's pin rises (its synchronizer), and falls about HOLD clocks after both are
// released.
//
// Parameters
//   HOLD   clocks rst stays high after lock and release, 4..65535 (the core needs 4)
//
// Ports
//   clk      the PLL's output clock
//   locked   the PLL's lock
//   button   the reset button, active high, asynchronous
//   rst      synchronous active-high reset for the design

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_power_on_reset #(
  parameter integer HOLD = 32
) (
  input  wire clk,
  input  wire locked,
  input  wire button,
  output wire rst
);

  generate
    if (HOLD < 4 || HOLD > 65535) begin : g_bad_hold
      initial $display("ERROR: %m: parameter HOLD = %0d is out of range 4..65535", HOLD);
      prenc_power_on_reset_parameter_HOLD_out_of_range_4_to_65535 u_stop ();
    end
  endgenerate

  localparam [31:0] LAST_32 = HOLD - 1;
  localparam [15:0] LAST    = LAST_32[15:0];

  reg [1:0]  button_sync;
  reg [15:0] count;
  reg        rst_reg;

  initial begin  // the configuration values
    button_sync = 2'b11;
    count       = 16'd0;
    rst_reg     = 1'b1;
  end

  always @(posedge clk) begin
    button_sync <= {button_sync[0], button};
    if (!locked || button_sync[1]) begin
      count   <= 16'd0;
      rst_reg <= 1'b1;
    end else if (count != LAST) begin
      count <= count + 16'd1;
    end else begin
      rst_reg <= 1'b0;
    end
  end

  assign rst = rst_reg;

endmodule

`resetall
