// SPDX-License-Identifier: Apache-2.0
// prenc_frame_rx: the host link's frame parser, bytes in, checked frames out.
//
// Frame (docs/host-protocol.md):  A5 | TYPE | LEN | PAYLOAD[LEN] | CRC16 hi | lo
// CRC-16/CCITT-FALSE (prenc_crc16) over TYPE, LEN and the payload.
//
// The parser hunts for the start byte A5, then follows the length. A frame is
// rejected, with one `frame_error` pulse, when its CRC differs, its LEN exceeds
// MAX_LEN, a byte inside it has a framing error, or the line stays idle for
// TIMEOUT clocks inside it; the parser then hunts for the next A5. Bytes between
// frames are ignored and not counted. The timeout is what resynchronises after a
// corrupted LEN: the host waits for an answer (far longer than TIMEOUT) before it
// sends again, so the parser is hunting again when the next frame starts.
//
// Parameters
//   MAX_LEN   largest payload accepted, 1..16 bytes
//   TIMEOUT   idle clocks that abort a frame, >= 1 (the board uses 2 byte times)
//
// Ports
//   clk, rst            one clock; synchronous active-high reset
//   byte_data, byte_valid, byte_error   from prenc_uart_rx
//   frame_valid         one clock: a frame passed its CRC
//   frame_type, frame_len, frame_payload   that frame (payload byte i at [8i+7:8i],
//                       bytes past LEN are zero); held until the next frame
//   frame_error         one clock: a frame was rejected

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_frame_rx #(
  parameter integer MAX_LEN = 5,
  parameter integer TIMEOUT = 1000
) (
  input  wire                   clk,
  input  wire                   rst,
  input  wire [7:0]             byte_data,
  input  wire                   byte_valid,
  input  wire                   byte_error,
  output wire                   frame_valid,
  output wire [7:0]             frame_type,
  output wire [7:0]             frame_len,
  output wire [8*MAX_LEN-1:0]   frame_payload,
  output wire                   frame_error
);

  generate
    if (MAX_LEN < 1 || MAX_LEN > 16) begin : g_bad_max_len
      initial $display("ERROR: %m: parameter MAX_LEN = %0d is out of range 1..16", MAX_LEN);
      prenc_frame_rx_parameter_MAX_LEN_out_of_range_1_to_16 u_stop ();
    end
    if (TIMEOUT < 1 || TIMEOUT > 16777215) begin : g_bad_timeout
      initial $display("ERROR: %m: parameter TIMEOUT = %0d is out of range 1..16777215", TIMEOUT);
      prenc_frame_rx_parameter_TIMEOUT_out_of_range_1_to_16777215 u_stop ();
    end
  endgenerate

  localparam [7:0]  SOF        = 8'hA5;
  localparam [31:0] MAX_LEN_32 = MAX_LEN;
  localparam [7:0]  MAX_LEN_8  = MAX_LEN_32[7:0];
  localparam [31:0] TIMEOUT_32 = TIMEOUT - 1;
  localparam [23:0] IDLE_LIMIT = TIMEOUT_32[23:0];

  localparam [2:0] HUNT    = 3'd0;
  localparam [2:0] TYPE    = 3'd1;
  localparam [2:0] LEN     = 3'd2;
  localparam [2:0] PAYLOAD = 3'd3;
  localparam [2:0] CRC_HI  = 3'd4;
  localparam [2:0] CRC_LO  = 3'd5;

  reg [2:0]             state;
  reg [7:0]             type_reg;
  reg [7:0]             len_reg;
  reg [7:0]             index;
  reg [8*MAX_LEN-1:0]   payload;
  reg [15:0]            crc;
  reg [7:0]             crc_hi;
  reg [23:0]            idle;
  reg                   valid_reg;
  reg                   error_reg;
  reg [7:0]             out_type;
  reg [7:0]             out_len;
  reg [8*MAX_LEN-1:0]   out_payload;

  wire [15:0] crc_next;

  prenc_crc16 u_crc (
    .crc_in  (crc),
    .data    (byte_data),
    .crc_out (crc_next)
  );

  always @(posedge clk) begin
    valid_reg <= 1'b0;
    error_reg <= 1'b0;
    if (state != HUNT) begin
      idle <= idle + 24'd1;
    end
    if (state != HUNT && (byte_error || (!byte_valid && idle == IDLE_LIMIT))) begin
      state     <= HUNT;
      error_reg <= 1'b1;
    end else if (byte_valid) begin
      idle <= 24'd0;
      case (state)
        HUNT: begin
          if (byte_data == SOF) begin
            state   <= TYPE;
            crc     <= 16'hFFFF;
            payload <= {8*MAX_LEN{1'b0}};
          end
        end
        TYPE: begin
          type_reg <= byte_data;
          crc      <= crc_next;
          state    <= LEN;
        end
        LEN: begin
          len_reg <= byte_data;
          crc     <= crc_next;
          index   <= 8'd0;
          if (byte_data > MAX_LEN_8) begin
            state     <= HUNT;
            error_reg <= 1'b1;
          end else if (byte_data == 8'd0) begin
            state <= CRC_HI;
          end else begin
            state <= PAYLOAD;
          end
        end
        PAYLOAD: begin
          payload <= payload | ({{8*MAX_LEN-8{1'b0}}, byte_data} << {index, 3'b000});
          crc     <= crc_next;
          index   <= index + 8'd1;
          if (index + 8'd1 == len_reg) begin
            state <= CRC_HI;
          end
        end
        CRC_HI: begin
          crc_hi <= byte_data;
          state  <= CRC_LO;
        end
        default: begin  // CRC_LO
          state <= HUNT;
          if ({crc_hi, byte_data} == crc) begin
            valid_reg   <= 1'b1;
            out_type    <= type_reg;
            out_len     <= len_reg;
            out_payload <= payload;
          end else begin
            error_reg <= 1'b1;
          end
        end
      endcase
    end
    if (rst) begin
      state       <= HUNT;
      idle        <= 24'd0;
      valid_reg   <= 1'b0;
      error_reg   <= 1'b0;
      out_type    <= 8'd0;
      out_len     <= 8'd0;
      out_payload <= {8*MAX_LEN{1'b0}};
    end
  end

  assign frame_valid   = valid_reg;
  assign frame_type    = out_type;
  assign frame_len     = out_len;
  assign frame_payload = out_payload;
  assign frame_error   = error_reg;

endmodule

`resetall
