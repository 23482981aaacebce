// SPDX-License-Identifier: Apache-2.0
// prenc_core_smoke: the FuseSoC smoke simulation of prenc_core (target `sim`, Icarus).
//
// The disc of the datasheet (formal/prenc_disc_reference.vh: the recurrence and the
// geometry, not the RTL's laws) turns 40 slots clockwise, then 40 slots back, one
// quarter every DWELL clocks; head 1 reads s(p), head 2 s(p + N - 1), the sync track
// A/B the quarter. The core must give its first valid position within N + 2 slots of
// travel, every valid pos_hyb must be the disc's hybrid position at the core's latency
// (7 + FILTER clocks after the pins: the edge that samples them, then the core's
// 6 + FILTER), and the position must be valid at the end of
// each way. Any failure stops with $fatal (exit status 1); success prints PASS.
`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_core_smoke #(
  parameter integer N        = 10,
  parameter [31:0]  TAPS     = 32'h0000_0204,
  parameter         ROM_FILE = "prenc_rom_n10.hex"
);

  localparam integer FILTER  = 2;
  localparam integer LATENCY = 7 + FILTER;
  localparam integer DWELL   = 6;
  localparam integer SLOTS   = 40;
  localparam integer START   = 4 * 100 + 1;

  `include "prenc_disc_reference.vh"

  reg clk = 1'b0;
  reg rst = 1'b1;
  always #5 clk = ~clk;

  reg  [N+1:0] h = START[N+1:0];
  wire [N-1:0] p  = h[N+1:2];
  wire [N-1:0] p2 = p + N[N-1:0] - 1'b1;
  wire         head1  = F_S[p];
  wire         head2  = F_S[p2];
  wire         sync_a = h[1];
  wire         sync_b = (h[1] == h[0]);

  wire [N-1:0]  pos_abs;
  wire [N+1:0]  pos_hyb;
  wire          pos_valid;
  wire [2:0]    mode;
  wire [N+1:0]  position;
  wire [31:0]   incremental;
  wire          direction;
  wire [N-1:0]  track1_pos;
  wire          track1_valid;
  wire [N-1:0]  track2_pos;
  wire          track2_valid;
  wire [15:0]   track1_errors;
  wire [15:0]   track2_errors;
  wire [15:0]   sync_errors;
  wire          track1_error;
  wire          track2_error;
  wire          sync_step;
  wire          sync_illegal;

  prenc_core #(
    .N        (N),
    .TAPS     (TAPS),
    .FILTER   (FILTER),
    .ROM_FILE (ROM_FILE)
  ) dut (
    .clk           (clk),
    .rst           (rst),
    .head1         (head1),
    .head2         (head2),
    .sync_a        (sync_a),
    .sync_b        (sync_b),
    .resolution    (1'b1),
    .clear_errors  (1'b0),
    .pos_abs       (pos_abs),
    .pos_hyb       (pos_hyb),
    .pos_valid     (pos_valid),
    .mode          (mode),
    .position      (position),
    .incremental   (incremental),
    .direction     (direction),
    .track1_pos    (track1_pos),
    .track1_valid  (track1_valid),
    .track2_pos    (track2_pos),
    .track2_valid  (track2_valid),
    .track1_errors (track1_errors),
    .track2_errors (track2_errors),
    .sync_errors   (sync_errors),
    .track1_error  (track1_error),
    .track2_error  (track2_error),
    .sync_step     (sync_step),
    .sync_illegal  (sync_illegal)
  );

  // The disc's position as the outputs show it: LATENCY clocks behind the pins.
  reg [N+1:0] h_d [0:LATENCY-1];
  integer d;
  always @(posedge clk) begin
    h_d[0] <= h;
    for (d = 1; d < LATENCY; d = d + 1) h_d[d] <= h_d[d - 1];
  end

  integer clocks   = 0;
  integer quarters = 0;      // quarters travelled since reset
  integer first    = -1;     // quarters travelled at the first valid position
  integer valid_clocks = 0;
  always @(negedge clk) begin
    if (!rst) begin
      clocks = clocks + 1;
      if (pos_valid) begin
        valid_clocks = valid_clocks + 1;
        if (first < 0) first = quarters;
        if (clocks > LATENCY && pos_hyb !== h_d[LATENCY - 1]) begin
          $display("prenc_core_smoke: FAIL at clock %0d: valid pos_hyb %0d, the disc %0d",
                   clocks, pos_hyb, h_d[LATENCY - 1]);
          $fatal(1, "a valid position that is not the disc's");
        end
      end
    end
  end

  task turn;
    input integer steps;
    input integer way;       // +1 clockwise, -1 counter-clockwise
    integer i;
    begin
      for (i = 0; i < steps; i = i + 1) begin
        repeat (DWELL) @(posedge clk);
        h <= (way > 0) ? h + 1'b1 : h - 1'b1;
        quarters = quarters + 1;
      end
      repeat (LATENCY + 2) @(posedge clk);
      if (pos_valid !== 1'b1) $fatal(1, "no valid position after %0d quarters", quarters);
    end
  endtask

  initial begin
    repeat (8) @(posedge clk);
    rst <= 1'b0;
    turn(4 * SLOTS, 1);
    if (first < 0 || first > 4 * (N + 2))
      $fatal(1, "first valid position after %0d quarters, more than N + 2 = %0d slots",
             first, N + 2);
    turn(4 * SLOTS, -1);
    $display("prenc_core_smoke: PASS: N = %0d, first valid after %0d.%02d slots, %0d of %0d clocks valid",
             N, first / 4, 25 * (first % 4), valid_clocks, clocks);
    $finish;
  end

endmodule

`resetall
