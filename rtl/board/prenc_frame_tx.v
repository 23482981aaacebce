// SPDX-License-Identifier: Apache-2.0
// prenc_frame_tx: the host link's frame sender, a frame in, bytes to the UART out.
//
// `start` takes TYPE, LEN and the payload (byte i at [8i+7:8i]) and sends
//   A5 | TYPE | LEN | PAYLOAD[LEN] | CRC16 hi | lo
// through prenc_uart_tx's ready/start handshake, computing the CRC-16/CCITT-FALSE
// (prenc_crc16) byte by byte. `busy` is high from `start` until the last byte has
// been handed to the UART.
//
// Latency: the first byte (A5) is offered to the UART the clock after `start`; each
// next byte when the UART is ready again, so a frame takes its bytes' time on the line.
//
// Parameters
//   MAX_LEN   largest payload, 1..16 bytes (LEN is clipped to it)
//
// Ports
//   clk, rst                      one clock; synchronous active-high reset
//   start, frame_type, frame_len, frame_payload   the frame, taken when !busy
//   busy                          a frame is being sent
//   byte_data, byte_start, byte_ready   to and from prenc_uart_tx

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_frame_tx #(
  parameter integer MAX_LEN = 16
) (
  input  wire                 clk,
  input  wire                 rst,
  input  wire                 start,
  input  wire [7:0]           frame_type,
  input  wire [7:0]           frame_len,
  input  wire [8*MAX_LEN-1:0] frame_payload,
  output wire                 busy,
  output wire [7:0]           byte_data,
  output wire                 byte_start,
  input  wire                 byte_ready
);

  generate
    if (MAX_LEN < 1 || MAX_LEN > 16) begin : g_bad_max_len
      initial $display("ERROR: %m: parameter MAX_LEN = %0d is out of range 1..16", MAX_LEN);
      prenc_frame_tx_parameter_MAX_LEN_out_of_range_1_to_16 u_stop ();
    end
  endgenerate

  localparam [7:0]  SOF        = 8'hA5;
  localparam [31:0] MAX_LEN_32 = MAX_LEN;
  localparam [7:0]  MAX_LEN_8  = MAX_LEN_32[7:0];

  reg                 busy_reg;
  reg [7:0]           index;     // byte of the frame being offered
  reg [7:0]           type_reg;
  reg [7:0]           len_reg;
  reg [7:0]           crc_hi_at; // index of the CRC's high byte: LEN + 3
  reg [7:0]           last;      // index of the CRC's low byte: LEN + 4
  reg [8*MAX_LEN-1:0] payload;
  reg [15:0]          crc;
  reg [7:0]           current;

  wire [7:0]  len_clipped = (frame_len > MAX_LEN_8) ? MAX_LEN_8 : frame_len;
  wire [15:0] crc_next;

  always @* begin
    if (index == 8'd0) begin
      current = SOF;
    end else if (index == 8'd1) begin
      current = type_reg;
    end else if (index == 8'd2) begin
      current = len_reg;
    end else if (index == crc_hi_at) begin
      current = crc[15:8];
    end else if (index == last) begin
      current = crc[7:0];
    end else begin
      current = payload[7:0];
    end
  end

  prenc_crc16 u_crc (
    .crc_in  (crc),
    .data    (current),
    .crc_out (crc_next)
  );

  always @(posedge clk) begin
    if (!busy_reg) begin
      if (start) begin
        busy_reg  <= 1'b1;
        index     <= 8'd0;
        type_reg  <= frame_type;
        len_reg   <= len_clipped;
        crc_hi_at <= len_clipped + 8'd3;
        last      <= len_clipped + 8'd4;
        payload   <= frame_payload;
        crc       <= 16'hFFFF;
      end
    end else if (byte_ready) begin
      index <= index + 8'd1;
      if (index != 8'd0 && index < crc_hi_at) begin
        crc <= crc_next;
      end
      if (index > 8'd2 && index < crc_hi_at) begin
        payload <= payload >> 8;
      end
      if (index == last) begin
        busy_reg <= 1'b0;
      end
    end
    if (rst) begin
      busy_reg <= 1'b0;
      index    <= 8'd0;
    end
  end

  assign busy       = busy_reg;
  assign byte_data  = current;
  assign byte_start = busy_reg & byte_ready;

endmodule

`resetall
