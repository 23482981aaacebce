// SPDX-License-Identifier: Apache-2.0
// prenc_uart_tx: UART transmitter, 8N1, LSB first.
//
// `start` with a byte while `ready` is high sends it: a start bit, 8 data bits and
// a stop bit, each CLKS_PER_BIT clocks long. `ready` rises again as the stop bit
// ends, so a byte offered on that clock follows with no idle gap.
//
// Latency: the start bit begins on the clock after `start & ready`; a byte takes 10 x
// CLKS_PER_BIT clocks.
//
// Parameters
//   CLKS_PER_BIT   clocks per bit, round(clock / baud), >= 4
//
// Ports
//   clk, rst      one clock; synchronous active-high reset (the line idles high)
//   data, start   the byte to send, taken when start & ready
//   ready         the transmitter can take a byte
//   tx            the serial line

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_uart_tx #(
  parameter integer CLKS_PER_BIT = 16
) (
  input  wire       clk,
  input  wire       rst,
  input  wire [7:0] data,
  input  wire       start,
  output wire       ready,
  output wire       tx
);

  generate
    if (CLKS_PER_BIT < 4 || CLKS_PER_BIT > 65535) begin : g_bad_clks_per_bit
      initial $display("ERROR: %m: parameter CLKS_PER_BIT = %0d is out of range 4..65535",
                       CLKS_PER_BIT);
      prenc_uart_tx_parameter_CLKS_PER_BIT_out_of_range_4_to_65535 u_stop ();
    end
  endgenerate

  localparam [31:0] FULL_32 = CLKS_PER_BIT - 1;
  localparam [15:0] FULL    = FULL_32[15:0];

  reg [9:0]  frame;      // stop, data[7:0], start; shifted out LSB first
  reg [3:0]  bits_left;  // 0: idle
  reg [15:0] timer;

  always @(posedge clk) begin
    if (bits_left == 4'd0) begin
      if (start) begin
        frame     <= {1'b1, data, 1'b0};
        bits_left <= 4'd10;
        timer     <= FULL;
      end
    end else if (timer != 16'd0) begin
      timer <= timer - 16'd1;
    end else begin
      frame     <= {1'b1, frame[9:1]};
      bits_left <= bits_left - 4'd1;
      timer     <= FULL;
    end
    if (rst) begin
      frame     <= 10'h3FF;
      bits_left <= 4'd0;
    end
  end

  assign ready = (bits_left == 4'd0);
  assign tx    = frame[0];

endmodule

`resetall
