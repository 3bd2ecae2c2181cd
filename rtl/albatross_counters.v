// albatross_counters -- the controller's per-channel counters and the STATUS
// words they make (docs/controller.md, "STATUS").
// Rules:
//   * Per channel, four 16-bit saturating counters: transfers (values
//     published), retries (failed accesses), abandoned (destinations that
//     still needed the value at the slot's end) and corrupt (control bytes
//     that named no buffer).  They live in one RAM of 2*N_CHAN 32-bit words
//     laid out as the STATUS words 1..2*N_CHAN: word 2c = {transfers,
//     retries}, word 2c+1 = {abandoned, corrupt}.  The RAM has one write and
//     one read port, is never reset, and is cleared by writing zeros after
//     reset (2*N_CHAN clocks; ready_o then goes high).
//   * During a slot the retries and corrupt counts of its channel are
//     counted in delta registers (one retry per clock at most; corrupt
//     arrives as counts); transfers_i and abandoned_i are the slot's totals,
//     sampled with commit_i only.  commit_i (one clock, chan_i valid, taken
//     when no commit runs) adds them to the channel's two words in three
//     clocks (read; write {transfers, retries} + read; write {abandoned,
//     corrupt}); a retry or corrupt event in those clocks is never lost: it
//     goes into the word still to be written, or counts towards the next
//     commit.  busy_o is high meanwhile.
//   * STATUS word 0 is {rom_errors_i, cycles_i}; word k >= 1 is RAM word
//     k - 1.  status_index_i selects the word; status_o is that word and
//     status_valid_o is high once the read of that index has completed (the
//     clock after the index was presented, if no commit uses the read port).
`default_nettype none

module albatross_counters #(
    parameter N_CHAN      = 32, // channels with counters, 1..128
    parameter INDEX_WIDTH = 12  // bits of status_index_i
) (
    input  wire                   clk_i,
    input  wire                   rst_i,          // synchronous, active high
    output wire                   ready_o,        // the RAM is cleared
    // events of the current slot's channel
    input  wire                   retry_i,        // a failed access
    input  wire [2:0]             transfers_i,    // values published in the slot (0..4), with commit_i
    input  wire [2:0]             abandoned_i,    // destinations abandoned (0..4), with commit_i
    input  wire [2:0]             corrupt_i,      // corrupt control bytes now (0..5)
    input  wire                   commit_i,       // the slot is over: add its deltas to chan_i
    input  wire [6:0]             chan_i,         // channel of the slot (sampled with commit_i)
    output wire                   busy_o,         // a commit is running
    // STATUS words
    input  wire [15:0]            rom_errors_i,
    input  wire [15:0]            cycles_i,
    input  wire [INDEX_WIDTH-1:0] status_index_i, // 0..2*N_CHAN
    output wire [31:0]            status_o,
    output wire                   status_valid_o
);

    localparam CB = $clog2(2 * N_CHAN);            // RAM address bits
    localparam integer    LAST_I = 2 * N_CHAN - 1;
    localparam [CB-1:0]   LAST   = LAST_I[CB-1:0];

    generate
        if (N_CHAN < 1 || N_CHAN > 128 || INDEX_WIDTH < CB + 1) begin : g_param_check
            albatross_counters_parameter_out_of_range u_error ();
        end
    endgenerate

    // A read never needs a word written in the same clock (phase 2 writes
    // word 2c and reads 2c+1; phase 3's read and the clearing's are not
    // used: rd_done_q stays low), so the RAM has no collision logic.
    (* no_rw_check *)
    reg [31:0]   ram [0:2*N_CHAN-1];
    reg [31:0]   rd_q;
    reg [CB-1:0] rd_next_q;     // the RAM word read last, + 1: its STATUS index (mod 2^CB), when rd_done_q
    reg          rd_done_q;     // rd_q holds the STATUS word of index rd_next_q
    reg          ready_q;
    reg [CB-1:0] clear_q;
    reg [1:0]    phase_q;       // commit: 0 none, 1 read word 2c, 2 write it + read 2c+1, 3 write that
    reg [15:0]   d_retry_q;
    reg [2:0]    xfer_q, aband_q;   // the committed slot's totals
    reg [3:0]    d_corrupt_q;
    reg          zero_q;        // status index 0 was presented
    reg [6:0]    chan_q;        // the channel being committed

    // a + b + ci, saturating at 2^16 - 1; ci enters as the adder's carry in
    // (bit 0 of {a, ci} + {b, ci}), so it adds no carry chain of its own.
    function [15:0] sat_add;
        input [15:0] a;
        input [15:0] b;
        input        ci;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [17:0] s;                   // bit 0 (unused): makes the carry in
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            s = {1'b0, a, ci} + {1'b0, b, ci};
            sat_add = s[17] ? 16'hFFFF : s[16:1];
        end
    endfunction

    // The deltas with this clock's events.
    // Saturating: the carry out of the increment says the count is at its top.
    wire [16:0] retry_inc = {1'b0, d_retry_q} + {16'd0, retry_i};
    wire [15:0] retry_n   = retry_inc[15:0] | {16{retry_inc[16]}};
    wire [3:0]  corrupt_n = d_corrupt_q + {1'b0, corrupt_i};

    // Channel words; the commit uses the read port in phases 1 and 2.
    /* verilator lint_off UNUSEDSIGNAL */
    wire [7:0]    w_wide = {chan_q, 1'b0};
    wire [CB-1:0] w0 = w_wide[CB-1:0];
    wire [CB-1:0] w1 = w0 | {{(CB-1){1'b0}}, 1'b1};
    wire [INDEX_WIDTH-1:0] idx_m1 = status_index_i - 1'b1;   // RAM word of STATUS word k
    /* verilator lint_on UNUSEDSIGNAL */
    wire [CB-1:0] rd_adr = (phase_q == 2'd1) ? w0 : (phase_q == 2'd2) ? w1 : idx_m1[CB-1:0];
    wire          wr     = !ready_q || phase_q == 2'd2 || phase_q == 2'd3;
    wire [CB-1:0] wr_adr = !ready_q ? clear_q : (phase_q == 2'd2) ? w0 : w1;
    // One pair of saturating adders: the deltas of the word being written.
    wire [2:0]    add_hi = (phase_q == 2'd2) ? xfer_q : aband_q;
    // The low word adds the retry delta and this clock's retry as the
    // adder's carry in (phase 2), not the saturated sum retry_n: with a
    // count c >= 0, min(c + min(d + r, 2^16 - 1), 2^16 - 1) = min(c + d + r,
    // 2^16 - 1), so the sum is the same and the failure that makes r is one
    // carry chain from the write data, not two.  In phase 3 the retry delta
    // is 0 (cleared in phase 2: that clock's retry counts towards the next
    // commit), so its high bits can feed the adder in both phases; only the
    // low four are selected.
    wire [15:0]   add_lo = {d_retry_q[15:4], (phase_q == 2'd2) ? d_retry_q[3:0] : corrupt_n};
    wire          add_ci = phase_q == 2'd2 && retry_i;
    wire [31:0]   wr_dat = !ready_q ? 32'd0 : {sat_add(rd_q[31:16], {13'd0, add_hi}, 1'b0), sat_add(rd_q[15:0], add_lo, add_ci)};

    // The STATUS index of the word read (rd_adr + 1) matters only for a read
    // made with no commit (rd_done_q): that read is of idx_m1, so its index
    // is status_index_i itself (no adder after the decrement, no multiplexer).
    wire [CB-1:0] rd_next = status_index_i[CB-1:0];

    always @(posedge clk_i) begin
        if (wr) ram[wr_adr] <= wr_dat;
        rd_q      <= ram[rd_adr];
        rd_next_q <= rd_next;
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            ready_q   <= 1'b0;
            clear_q   <= {CB{1'b0}};
            phase_q   <= 2'd0;
            rd_done_q <= 1'b0;
            d_retry_q <= 16'd0;
            d_corrupt_q <= 4'd0;
        end else begin
            if (!ready_q) begin
                clear_q <= clear_q + 1'b1;
                if (clear_q == LAST) ready_q <= 1'b1;
            end
            rd_done_q <= phase_q == 2'd0;
            // Word 0's deltas go into the RAM in phase 2, word 1's in phase 3
            // (with that clock's events); later events count from zero.
            d_retry_q   <= (phase_q == 2'd2) ? 16'd0 : retry_n;
            d_corrupt_q <= (phase_q == 2'd3) ? 4'd0 : corrupt_n;
            case (phase_q)
                2'd0: if (commit_i) begin
                    phase_q <= 2'd1;
                    chan_q  <= chan_i;
                    xfer_q  <= transfers_i;
                    aband_q <= abandoned_i;
                end
                2'd1: phase_q <= 2'd2;
                2'd2: phase_q <= 2'd3;
                default: phase_q <= 2'd0;
            endcase
        end
    end


    always @(posedge clk_i) zero_q <= status_index_i == {INDEX_WIDTH{1'b0}};

    assign ready_o        = ready_q;
    assign busy_o         = phase_q != 2'd0;
    assign status_o       = zero_q ? {rom_errors_i, cycles_i} : rd_q;
    assign status_valid_o = (zero_q && status_index_i == {INDEX_WIDTH{1'b0}}) || (rd_done_q && rd_next_q == status_index_i[CB-1:0] && status_index_i != {INDEX_WIDTH{1'b0}});

endmodule

`default_nettype wire
