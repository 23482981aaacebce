// SPDX-License-Identifier: Apache-2.0
// prenc_crc16: one byte of CRC-16/CCITT-FALSE, combinational.
//
// Polynomial x^16 + x^12 + x^5 + 1 (0x1021), MSB first, no reflection, no final
// XOR; a frame's CRC starts at 16'hFFFF. This is Python's binascii.crc_hqx(data,
// 0xFFFF), the reference the host protocol (prenc.link.protocol) uses.
//
// Latency: none, combinational.
//
// Ports
//   crc_in    CRC before the byte
//   data      the byte
//   crc_out   CRC after the byte

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_crc16 (
  input  wire [15:0] crc_in,
  input  wire [7:0]  data,
  output wire [15:0] crc_out
);

  // Eight shifts of the bitwise algorithm, unrolled.
  reg [15:0] crc;
  integer    i;

  always @* begin
    crc = crc_in ^ {data, 8'h00};
    for (i = 0; i < 8; i = i + 1) begin
      crc = crc[15] ? ({crc[14:0], 1'b0} ^ 16'h1021) : {crc[14:0], 1'b0};
    end
  end

  assign crc_out = crc;

endmodule

`resetall
