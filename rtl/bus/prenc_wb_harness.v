// SPDX-License-Identifier: Apache-2.0
// prenc_wb_harness: prenc_wb with few pins, for place and route on small packages
// (iCE40 UP5K SG48): a free-running LFSR plays the bus master (cycle, strobe, write,
// address, data, byte selects) and the read data, ack and irq fold into one pin, so that
// no register of the map can be optimized away and the timing seen is the bus's own.
// Used by `scripts/synth.py --core <target> --top prenc_wb_harness`; not for designs.
//
// Parameters: N, TAPS, FILTER, ROM_FILE, FINE (1), CAL (0) as prenc_wb.
//
// Latency: not meaningful; the harness exists for synthesis only (every register of the
// map kept, the bus's own timing seen).

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_wb_harness #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter integer FILTER   = 2,
  parameter         ROM_FILE = "prenc_rom_n10.hex",
  parameter integer FINE     = 1,
  parameter integer CAL      = 0
) (
  input  wire clk,
  input  wire rst,
  input  wire head1,
  input  wire head2,
  input  wire sync_a,
  input  wire sync_b,
  output reg  probe
);

  // x^64 + x^63 + x^61 + x^60 + 1, a maximal-length Fibonacci LFSR.
  reg  [63:0] lfsr;
  wire        feedback = lfsr[63] ^ lfsr[62] ^ lfsr[60] ^ lfsr[59];
  always @(posedge clk) begin
    if (rst) lfsr <= 64'h1;
    else     lfsr <= {lfsr[62:0], feedback};
  end

  wire [31:0]  dat_o;
  wire         ack;
  wire         err;
  wire         irq;
  wire [N+1:0] pos_hyb;
  wire         pos_valid;

  prenc_wb #(
    .N        (N),
    .TAPS     (TAPS),
    .FILTER   (FILTER),
    .ROM_FILE (ROM_FILE),
    .FINE     (FINE),
    .CAL      (CAL)
  ) u_wb (
    .clk       (clk),
    .rst       (rst),
    .head1     (head1),
    .head2     (head2),
    .sync_a    (sync_a),
    .sync_b    (sync_b),
    .wb_cyc_i  (lfsr[0]),
    .wb_stb_i  (lfsr[1]),
    .wb_we_i   (lfsr[2] & lfsr[3]),
    .wb_adr_i  (lfsr[8:4]),
    .wb_dat_i  (lfsr[40:9]),
    .wb_sel_i  (lfsr[44:41]),
    .wb_dat_o  (dat_o),
    .wb_ack_o  (ack),
    .wb_err_o  (err),
    .irq       (irq),
    .pos_hyb   (pos_hyb),
    .pos_valid (pos_valid)
  );

  always @(posedge clk) begin
    probe <= ^{dat_o, ack, err, irq, pos_hyb, pos_valid};
  end

  wire unused_ok = &{1'b0, lfsr[63:45]};

endmodule

`resetall
