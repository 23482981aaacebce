// SPDX-License-Identifier: Apache-2.0
// prenc_matrix_encoder: a matrix-code absolute encoder with an SSI output.
//
// The matrix reader (prenc_matrix_reader) on the image sensor's pixel stream, its
// last reading held and sent by prenc_ssi: A position bits, Gray or binary, and the
// error bit (1 when the last reading was not trusted: low contrast, an uncertain
// cell, a parity failure, or the table not built yet). The few pins it needs fit
// the iCE40 UP5K's SG48 package; with TABLE = "generator" and N = 4 the 64 Ki-word
// table goes to the UP5K's four SPRAMs.
//
// Latency: the reader's (a reading N*N + 5 clocks after the frame's last pixel), then
// the SSI frame latches the last reading at the controller's first falling edge.
//
// Parameters: as prenc_matrix_reader, plus MONOFLOP (prenc_ssi).
// Ports
//   clk, rst                         one clock; synchronous active-high reset
//   pixel_valid, pixel_first, pixel  the sensor's pixel stream (prenc_matrix_reader)
//   gray                             1: Gray-coded SSI position
//   ssi_clk, ssi_data                the SSI line
//   ready                            the table is built
//   ok                               the position held is trusted (an LED)

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_matrix_encoder #(
  parameter integer N            = 4,
  parameter integer CHECKSUM     = 0,
  parameter integer CELL         = 3,
  parameter integer WIDTH        = 15,
  parameter integer HEIGHT       = 15,
  parameter integer TOP          = 1,
  parameter integer PIXEL_BITS   = 8,
  parameter integer MIN_CONTRAST = 32,
  parameter [71:0]  TABLE        = "generator",
  parameter         TABLE_FILE   = "prenc_matrix_n4.hex",
  parameter integer MONOFLOP     = 480,
  // derived; do not override
  parameter integer A            = N * (N - CHECKSUM),
  parameter integer PHASE_BITS   = (CELL > 1) ? $clog2(CELL) : 1
) (
  input  wire                  clk,
  input  wire                  rst,
  input  wire                  pixel_valid,
  input  wire                  pixel_first,
  input  wire [PIXEL_BITS-1:0] pixel,
  input  wire                  gray,
  input  wire                  ssi_clk,
  output wire                  ssi_data,
  output wire                  ready,
  output reg                   ok
);

  wire                  out_valid;
  wire [A-1:0]          out_position;
  wire [PHASE_BITS-1:0] out_phase;
  wire [N*N-1:0]        out_cells;
  wire                  out_ok;
  wire                  out_low_contrast;
  wire                  out_uncertain;
  wire                  out_checksum_error;
  wire                  reader_busy;
  wire                  ssi_busy;
  reg  [A-1:0]          position_reg;

  prenc_matrix_reader #(
    .N            (N),
    .CHECKSUM     (CHECKSUM),
    .CELL         (CELL),
    .WIDTH        (WIDTH),
    .HEIGHT       (HEIGHT),
    .TOP          (TOP),
    .PIXEL_BITS   (PIXEL_BITS),
    .MIN_CONTRAST (MIN_CONTRAST),
    .TABLE        (TABLE),
    .TABLE_FILE   (TABLE_FILE)
  ) u_reader (
    .clk                (clk),
    .rst                (rst),
    .pixel_valid        (pixel_valid),
    .pixel_first        (pixel_first),
    .pixel              (pixel),
    .ready              (ready),
    .busy               (reader_busy),
    .out_valid          (out_valid),
    .out_position       (out_position),
    .out_phase          (out_phase),
    .out_cells          (out_cells),
    .out_ok             (out_ok),
    .out_low_contrast   (out_low_contrast),
    .out_uncertain      (out_uncertain),
    .out_checksum_error (out_checksum_error)
  );

  always @(posedge clk) begin
    if (out_valid) begin
      position_reg <= out_position;
      ok           <= out_ok;
    end
    if (rst) begin
      position_reg <= {A{1'b0}};
      ok           <= 1'b0;
    end
  end

  prenc_ssi #(
    .WIDTH     (A),
    .ERROR_BIT (1),
    .MONOFLOP  (MONOFLOP)
  ) u_ssi (
    .clk      (clk),
    .rst      (rst),
    .position (position_reg),
    .valid    (ok),
    .warn     (1'b0),
    .gray     (gray),
    .ssi_clk  (ssi_clk),
    .ssi_data (ssi_data),
    .busy     (ssi_busy)
  );

  // The flags, phase, cells and busy lines are for a wider host interface; this
  // top keeps them internal.
  wire unused = &{1'b0, out_phase, out_cells, out_low_contrast, out_uncertain,
                  out_checksum_error, reader_busy, ssi_busy};

endmodule

`resetall
