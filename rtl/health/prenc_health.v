// SPDX-License-Identifier: Apache-2.0
// prenc_health: the warning before a failure (docs/health.md).
//
// The reader corrects what its heads read: a reading that disagrees with the disc's law
// (prenc_core's track1_error, track2_error: what its error counters count) and an
// illegal transition of the sync track (sync_illegal) are corrections. The position
// survives them, but they grow as a disc gets dirty or a head weakens, long before the
// reader must drop a track or the position. This block watches how often they come.
//
// Each source (head 1, head 2, the sync track) has a level, a leaky bucket counted in
// quarters of travel: a correction adds 4 x WARN_SLOTS, each quarter step of the sync
// track (either way) takes one off. Corrections more often than one per WARN_SLOTS
// slots of travel fill the bucket, and so does a burst of WARN_BURST corrections. At
// the limit, 4 x WARN_SLOTS x WARN_BURST, the source warns, and it warns until its
// level is back to 0: at least WARN_SLOTS x WARN_BURST slots of travel after the last
// correction. A disc that stands still neither fills nor drains a bucket.
//
// Latency: a correction at the limit shows on `warnings` one clock later.
//
// Parameters
//   WARN_SLOTS   slots of travel per correction that a source may have, 1..4096 (128)
//   WARN_BURST   corrections at once that warn, 1..64 (8)
//
// Ports
//   clk, rst       one clock; synchronous active-high reset
//   step           one clock: the sync track made a quarter step (prenc_core's sync_step)
//   track1_error, track2_error, sync_illegal   one clock each: a correction
//   warnings       {sync, head 2, head 1}: that source warns
//   warning        any source warns

`resetall
`timescale 1ns / 1ps
`default_nettype none

module prenc_health #(
  parameter integer WARN_SLOTS = 128,
  parameter integer WARN_BURST = 8
) (
  input  wire       clk,
  input  wire       rst,
  input  wire       step,
  input  wire       track1_error,
  input  wire       track2_error,
  input  wire       sync_illegal,
  output wire [2:0] warnings,
  output wire       warning
);

  generate
    if (WARN_SLOTS < 1 || WARN_SLOTS > 4096) begin : g_bad_slots
      initial $display("ERROR: %m: parameter WARN_SLOTS = %0d is out of range 1..4096",
                       WARN_SLOTS);
      prenc_health_parameter_WARN_SLOTS_out_of_range_1_to_4096 u_stop ();
    end
    if (WARN_BURST < 1 || WARN_BURST > 64) begin : g_bad_burst
      initial $display("ERROR: %m: parameter WARN_BURST = %0d is out of range 1..64",
                       WARN_BURST);
      prenc_health_parameter_WARN_BURST_out_of_range_1_to_64 u_stop ();
    end
  endgenerate

  localparam integer LW       = $clog2(4 * WARN_SLOTS * WARN_BURST + 1);   // level bits
  localparam [31:0]  LIMIT32  = 4 * WARN_SLOTS * WARN_BURST;   // 4 .. 2^20 quarters
  localparam [31:0]  WEIGHT32 = 4 * WARN_SLOTS;               // a correction, in quarters
  localparam [LW-1:0] LIMIT   = LIMIT32[LW-1:0];
  localparam [LW-1:0] WEIGHT  = WEIGHT32[LW-1:0];
  localparam [LW-1:0] FILLS   = LIMIT - WEIGHT;   // a correction from here on fills the bucket
  localparam [LW-1:0] ONE     = {{(LW - 1){1'b0}}, 1'b1};

  wire [2:0] event_in = {sync_illegal, track2_error, track1_error};
  wire [2:0] warn;

  // One source's next level: + WEIGHT on a correction, capped at LIMIT; - 1 on a quarter
  // step while it is above 0. The comparisons are with constants on the level as it is,
  // so one adder is all that lies between the registers.
  genvar k;
  for (k = 0; k < 3; k = k + 1) begin : g_source
    reg [LW-1:0] level;
    reg          warn_reg;
    wire high;   // a correction now fills the bucket (WARN_BURST = 1: any)
    if (WARN_BURST == 1) begin : g_any
      assign high = 1'b1;
    end else begin : g_above
      assign high = level >= FILLS;
    end
    wire fills  = event_in[k] && high;
    wire drains = step && (event_in[k] || level != {LW{1'b0}});
    wire empty  = !event_in[k] && (level == {LW{1'b0}} || (level == ONE && step));
    wire [LW-1:0] added = level + (event_in[k] ? WEIGHT : {LW{1'b0}});
    assign warn[k] = warn_reg;
    always @(posedge clk) begin
      if (fills) begin
        level    <= drains ? LIMIT - ONE : LIMIT;
        warn_reg <= 1'b1;
      end else begin
        level    <= drains ? added - ONE : added;
        if (empty) warn_reg <= 1'b0;
      end
      if (rst) begin
        level    <= {LW{1'b0}};
        warn_reg <= 1'b0;
      end
    end
  end

  assign warnings = warn;
  assign warning  = |warn;

endmodule

`resetall
