// SPDX-License-Identifier: Apache-2.0
// prenc_wb_smoke: the FuseSoC smoke simulation of prenc_wb (target `sim`, Icarus).
//
// The datasheet's disc (formal/prenc_disc_reference.vh) turns 40 slots clockwise and
// stops; then, as a CPU would, a Wishbone master reads ID, takes a snapshot and reads it
// back: ID must be 'prnc', the snapshot valid, SNAP_POS_HYB and POS_ABS the disc's
// position. Any failure stops with $fatal (exit status 1); success prints PASS.
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_wb_smoke #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter         ROM_FILE = "prenc_rom_n10.hex"
);

  localparam integer DWELL = 6;
  localparam integer START = 4 * 300 + 2;

  `include "prenc_disc_reference.vh"

  reg clk = 1'b0;
  reg rst = 1'b1;
  always #5 clk = ~clk;

  reg  [N+1:0] h = START[N+1:0];
  wire [N-1:0] p  = h[N+1:2];
  wire [N-1:0] p2 = p + N[N-1:0] - 1'b1;

  reg         cyc = 1'b0;
  reg         stb = 1'b0;
  reg         we  = 1'b0;
  reg  [4:0]  adr = 5'd0;
  reg  [31:0] dat = 32'd0;
  wire [31:0] dat_o;
  wire        ack;
  wire        err;
  wire        irq;
  wire [N+1:0] pos_hyb;
  wire         pos_valid;

  prenc_wb #(
    .N        (N),
    .TAPS     (TAPS),
    .ROM_FILE (ROM_FILE)
  ) dut (
    .clk       (clk),
    .rst       (rst),
    .head1     (F_S[p]),
    .head2     (F_S[p2]),
    .sync_a    (h[1]),
    .sync_b    (h[1] == h[0]),
    .wb_cyc_i  (cyc),
    .wb_stb_i  (stb),
    .wb_we_i   (we),
    .wb_adr_i  (adr),
    .wb_dat_i  (dat),
    .wb_sel_i  (4'hF),
    .wb_dat_o  (dat_o),
    .wb_ack_o  (ack),
    .wb_err_o  (err),
    .irq       (irq),
    .pos_hyb   (pos_hyb),
    .pos_valid (pos_valid)
  );

  // One classic Wishbone access; the read data in `word`.
  reg [31:0] word;
  task access;
    input        write;
    input [7:0]  offset;
    input [31:0] data;
    begin
      @(negedge clk);
      cyc = 1'b1;
      stb = 1'b1;
      we  = write;
      adr = offset[6:2];
      dat = data;
      @(posedge clk);
      while (!ack) @(posedge clk);
      word = dat_o;
      @(negedge clk);
      cyc = 1'b0;
      stb = 1'b0;
      we  = 1'b0;
    end
  endtask

  integer i;
  initial begin
    repeat (8) @(posedge clk);
    rst <= 1'b0;
    for (i = 0; i < 4 * 40; i = i + 1) begin
      repeat (DWELL) @(posedge clk);
      h <= h + 1'b1;
    end
    repeat (30) @(posedge clk);
    access(1'b0, 8'h00, 32'd0);
    if (word !== 32'h7072_6E63) $fatal(1, "ID reads %h, not 'prnc'", word);
    access(1'b1, 8'h0C, 32'h0000_0005);  // CTRL: resolution 1, snapshot
    access(1'b0, 8'h44, 32'd0);          // SNAP_STATUS
    if (word[0] !== 1'b1) $fatal(1, "no valid position after 40 slots (SNAP_STATUS %h)", word);
    access(1'b0, 8'h40, 32'd0);          // SNAP_POS_HYB
    if (word !== {{(30 - N){1'b0}}, h}) $fatal(1, "SNAP_POS_HYB %0d, the disc %0d", word, h);
    access(1'b0, 8'h18, 32'd0);          // POS_ABS
    if (word !== {{(32 - N){1'b0}}, h[N+1:2]}) $fatal(1, "POS_ABS %0d, the disc %0d", word, h[N+1:2]);
    $display("prenc_wb_smoke: PASS: N = %0d, position %0d read over Wishbone", N, h);
    $finish;
  end

endmodule

`resetall
