// SPDX-License-Identifier: Apache-2.0
// prenc_uart_rx: UART receiver, 8 data bits, no parity, 1 stop bit (8N1), LSB first.
//
// The line goes through a two-flop synchronizer. A falling edge starts a byte; the
// start bit is checked again half a bit later (a shorter pulse is noise and is
// ignored), then every bit is sampled once, in its middle, CLKS_PER_BIT clocks
// apart. A low stop bit is a framing error: the byte is dropped, `frame_error`
// pulses, and the receiver waits for the line to go high (a break) before it
// looks for the next start bit.
//
// Parameters
//   CLKS_PER_BIT   clocks per bit, round(clock / baud), >= 4
//
// Ports
//   clk, rst      one clock; synchronous active-high reset
//   rx            the asynchronous serial line (idle high)
//   data, valid   a received byte, `valid` high for one clock
//   frame_error   one clock: a byte with a low stop bit was dropped
//   busy          a byte is being received (from the start bit to the stop bit)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_uart_rx #(
  parameter integer CLKS_PER_BIT = 16
) (
  input  wire       clk,
  input  wire       rst,
  input  wire       rx,
  output wire [7:0] data,
  output wire       valid,
  output wire       frame_error,
  output wire       busy
);

  generate
    if (CLKS_PER_BIT < 4 || CLKS_PER_BIT > 65535) begin : g_bad_clks_per_bit
      initial $display("ERROR: %m: parameter CLKS_PER_BIT = %0d is out of range 4..65535",
                       CLKS_PER_BIT);
      prenc_uart_rx_parameter_CLKS_PER_BIT_out_of_range_4_to_65535 u_stop ();
    end
  endgenerate

  localparam [31:0] FULL_32 = CLKS_PER_BIT - 1;
  localparam [31:0] HALF_32 = CLKS_PER_BIT / 2 - 1;
  localparam [15:0] FULL    = FULL_32[15:0];
  localparam [15:0] HALF    = HALF_32[15:0];

  localparam [1:0] IDLE  = 2'd0;
  localparam [1:0] START = 2'd1;
  localparam [1:0] BITS  = 2'd2;
  localparam [1:0] BREAK = 2'd3;

  reg        rx_q1;
  reg        rx_q2;
  reg [1:0]  state;
  reg [15:0] timer;
  reg [3:0]  bit_index;  // 0..7 data, 8 stop
  reg [7:0]  shift;
  reg        valid_reg;
  reg        error_reg;

  always @(posedge clk) begin
    rx_q1     <= rx;
    rx_q2     <= rx_q1;
    valid_reg <= 1'b0;
    error_reg <= 1'b0;
    case (state)
      IDLE: begin
        if (!rx_q2) begin
          state <= START;
          timer <= HALF;
        end
      end
      START: begin
        if (timer != 16'd0) begin
          timer <= timer - 16'd1;
        end else if (rx_q2) begin
          state <= IDLE;  // too short for a start bit
        end else begin
          state     <= BITS;
          timer     <= FULL;
          bit_index <= 4'd0;
        end
      end
      BITS: begin
        if (timer != 16'd0) begin
          timer <= timer - 16'd1;
        end else if (bit_index != 4'd8) begin
          shift     <= {rx_q2, shift[7:1]};
          bit_index <= bit_index + 4'd1;
          timer     <= FULL;
        end else if (rx_q2) begin
          state     <= IDLE;
          valid_reg <= 1'b1;
        end else begin
          state     <= BREAK;
          error_reg <= 1'b1;
        end
      end
      default: begin  // BREAK: wait for the idle level
        if (rx_q2) begin
          state <= IDLE;
        end
      end
    endcase
    if (rst) begin
      rx_q1     <= 1'b1;
      rx_q2     <= 1'b1;
      state     <= IDLE;
      valid_reg <= 1'b0;
      error_reg <= 1'b0;
    end
  end

  assign data        = shift;
  assign valid       = valid_reg;
  assign frame_error = error_reg;
  assign busy        = (state == START) | (state == BITS);

endmodule

`resetall
