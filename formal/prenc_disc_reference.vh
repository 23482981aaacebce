// SPDX-License-Identifier: Apache-2.0
// The disc for formal properties, built from the datasheet (docs/encoder-disc.md),
// not from the RTL's laws: the recurrence s(k) = XOR over t in TAPS of s(k - t) from
// the seed s(0..N-1) = 1, 0, ..., 0, then one extra 0 inserted into the run of N - 1
// zeros (after s(0)), so that W(0) = 1 0 ... 0 and W(1) = 0 ... 0.
// Included inside `ifdef FORMAL by a module with parameters N and TAPS; defines
// F_L (= 2^N) and F_S (bit k = s(k)), and the function f_window(p) = W(p).
localparam integer F_L = 1 << N;
function automatic [F_L-1:0] f_disc;
  input integer unused;
  integer       k;
  integer       t;
  reg [F_L-1:0] m;
  begin
    m = {F_L{1'b0}};
    m[0] = 1'b1;
    for (k = N; k < F_L - 1; k = k + 1) begin
      for (t = 1; t <= N; t = t + 1) begin
        if (TAPS[t - 1]) m[k] = m[k] ^ m[k - t];
      end
    end
    f_disc = {F_L{1'b0}};
    f_disc[0] = m[0];
    for (k = 1; k < F_L - 1; k = k + 1) begin
      f_disc[k + 1] = m[k];
    end
  end
endfunction
localparam [F_L-1:0] F_S = f_disc(0);
function automatic [N-1:0] f_window;
  input integer p;
  integer j;
  begin
    for (j = 0; j < N; j = j + 1) begin
      f_window[N - 1 - j] = F_S[(p + j) % F_L];
    end
  end
endfunction
