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

  // The byte being offered: the frame's fields in order (a phase per field, the payload
  // counted down), so that the byte and the CRC it goes into come from registers
  // through a multiplexer of six, not through comparisons of a byte index.
  localparam [2:0] P_SOF = 3'd0, P_TYPE = 3'd1, P_LEN = 3'd2, P_DATA = 3'd3,
                   P_CRC_HI = 3'd4, P_CRC_LO = 3'd5;

  reg                 busy_reg;
  reg [2:0]           phase;
  reg [7:0]           left;      // payload bytes left, this one included (P_DATA)
  reg [7:0]           type_reg;
  reg [7:0]           len_reg;
  reg [8*MAX_LEN-1:0] payload;
  reg [15:0]          crc;
  reg [7:0]           current;

  wire [7:0]  len_clipped = (frame_len > MAX_LEN_8) ? MAX_LEN_8 : frame_len;
  wire [15:0] crc_next;
  wire        in_crc = (phase == P_TYPE) || (phase == P_LEN) || (phase == P_DATA);

  always @* begin
    case (phase)
      P_SOF:    current = SOF;
      P_TYPE:   current = type_reg;
      P_LEN:    current = len_reg;
      P_CRC_HI: current = crc[15:8];
      P_CRC_LO: current = crc[7:0];
      default:  current = payload[7:0];
    endcase
  end

  prenc_crc16 u_crc (
    .crc_in  (crc),
    .data    (current),
    .crc_out (crc_next)
  );

  always @(posedge clk) begin
    if (!busy_reg) begin
      if (start) begin
        busy_reg <= 1'b1;
        phase    <= P_SOF;
        type_reg <= frame_type;
        len_reg  <= len_clipped;
        left     <= len_clipped;
        payload  <= frame_payload;
        crc      <= 16'hFFFF;
      end
    end else if (byte_ready) begin
      if (in_crc) begin
        crc <= crc_next;
      end
      case (phase)
        P_SOF:  phase <= P_TYPE;
        P_TYPE: phase <= P_LEN;
        P_LEN:  phase <= (left == 8'd0) ? P_CRC_HI : P_DATA;
        P_DATA: begin
          payload <= payload >> 8;
          left    <= left - 8'd1;
          if (left == 8'd1) phase <= P_CRC_HI;
        end
        P_CRC_HI: phase <= P_CRC_LO;
        default: busy_reg <= 1'b0;   // P_CRC_LO: the last byte
      endcase
    end
    if (rst) begin
      busy_reg <= 1'b0;
      phase    <= P_SOF;
    end
  end

  assign busy       = busy_reg;
  assign byte_data  = current;
  assign byte_start = busy_reg & byte_ready;

endmodule

`resetall
