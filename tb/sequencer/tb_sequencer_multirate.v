// tb_sequencer_multirate -- self-checking Icarus bench of albatross_sequencer
// on a multi-rate image (make_rom.py --multirate, --multirate-modes), cycle
// by cycle against its own model of the contract, which it decodes from the
// ROM words (bit positions of docs/controller.md, written here as literals):
//   * the minor-cycle count n is 0 in the first cycle after start-up and
//     after a mode switch, + 1 at each other cycle start, modulo 2^c (c: the
//     running mode's cluster, H2[23:20] or its descriptor's D2[23:20]);
//   * an entry is valid when rep <= c (E6: base [14:0], rep [19:16]); it is
//     due when n mod 2^rep = base mod 2^rep: the controller reads only
//     base's low rep bits (base < 2^rep is a rule of the image that
//     verify_rom checks, not the controller), so an entry with base >= 2^rep
//     runs in those cycles: the image has one, and the bench fails unless it
//     ran (and every entry ran in exactly the cycles the model counts);
//   * every entry is fetched in every cycle, at S = max(cycle start + E1, the
//     clock after the previous entry ended): a valid due entry gets go_o at
//     S + 6 with slot_time_o = S and its fields, and its accesses stop TIMEOUT
//     + 2 clocks before its deadline (E1 + E2); an entry not due or invalid
//     costs its fetch: the next entry's S is S + 7 at the earliest;
//   * rom_errors_o grows by the number of invalid entries of the mode in each
//     cycle; no go comes for an entry that is not due (a go the model does
//     not expect is a failure), and no due entry is left out.
// +modes (--multirate-modes): requests switch to mode 1 (cluster 2) and back,
// mid-cluster; the count restarts at 0 in each mode's first cycle.
`timescale 1ns/1ps
`default_nettype none
module tb_sequencer_multirate;
    reg clk = 0, rst = 1;
    always #5 clk = !clk;
    wire go, may, cyc_s, error;
    wire [1:0] kind; wire [6:0] chan; wire [2:0] nd; wire [11:0] words;
    wire [3:0] sb; wire [9:0] sbase; wire [15:0] db; wire [39:0] dbase;
    wire [31:0] slot_time, t; wire [15:0] rerr, cycles;
    wire poll_cyc; wire [3:0] pb; wire [9:0] pa;
    reg done = 0;
    reg mreq = 0; reg [3:0] mreq_mode = 0;
    wire [3:0] mode; wire mreject;
    albatross_sequencer #(.NB(4), .ADDR_WIDTH(10), .N_CHAN(4), .ROM_WORDS(128), .ROM_FILE("seq_rom.hex"),
                          .TIME_BITS(12), .TIMEOUT(8), .POLL(16)) dut (
        .clk_i(clk), .rst_i(rst), .enable_i(1'b1),
        .go_o(go), .kind_o(kind), .chan_o(chan), .nd_o(nd), .words_o(words), .src_board_o(sb), .src_base_o(sbase),
        .dst_board_o(db), .dst_base_o(dbase), .slot_time_o(slot_time), .may_access_o(may), .slot_done_i(done),
        .poll_cyc_o(poll_cyc), .poll_board_o(pb), .poll_adr_o(pa), .poll_dat_i(32'd0), .poll_ack_i(1'b0),
        .poll_err_i(1'b0), .sync_rl_i(2'd0),
        .time_o(t), .cycle_o(cyc_s), .error_o(error), .rom_errors_o(rerr), .cycles_o(cycles),
        .mode_req_i(mreq), .mode_req_mode_i(mreq_mode), .mode_o(mode), .mode_reject_o(mreject));

    // ------------------------------------------------------------ the image, decoded
    integer ne, nmodes, m_first [0:1], m_end [0:1], m_cycle [0:1], m_cl [0:1];
    integer e_kind [0:15], e_chan [0:15], e_start [0:15], e_len [0:15], e_rep [0:15], e_base [0:15];
    integer i, w;
    function integer word; input integer a; word = dut.u_rom.rom[a]; endfunction
    initial begin
        #1;
        ne = (word(0) >> 8) & 255;
        nmodes = (word(2) >> 16) & 15;
        if (nmodes == 0) begin
            m_first[0] = 0; m_end[0] = ne; m_cycle[0] = word(1) & 16'hFFFF; m_cl[0] = (word(2) >> 20) & 15;
        end else for (i = 0; i < nmodes; i = i + 1) begin
            w = 4 + 8 * (((word(2) >> 8) & 255) + i);       // descriptor i in the place of entry table + i
            m_first[i] = (word(w) >> 16) & 255; m_end[i] = (word(w) >> 24) & 255; m_cycle[i] = word(w) & 16'hFFFF;
            m_cl[i] = (word(w + 2) >> 20) & 15;
        end
        for (i = 0; i < ne && i < 16; i = i + 1) begin
            w = 4 + 8 * i;
            e_kind[i] = (word(w) >> 28) & 15; e_chan[i] = (word(w) >> 16) & 255;
            e_start[i] = word(w + 1) & 16'hFFFF; e_len[i] = word(w + 2) & 16'hFFFF;
            e_rep[i] = (word(w + 6) >> 16) & 15; e_base[i] = word(w + 6) & 16'h7FFF;
        end
    end
    function valid; input integer j; input integer m;
        valid = e_rep[j] <= m_cl[m];
    endfunction
    function due; input integer j; input integer n;
        due = n % (1 << e_rep[j]) == e_base[j] % (1 << e_rep[j]);
    endfunction

    // ------------------------------------------------------------ the model, checked at every go and cycle start
    integer errors = 0, gos = 0, cyc_n = 0, cur_mode = 0, n = 0, cstart = -1, k = 0, t_free = 0, s = 0, j = 0;
    integer cur = 0, last_may = 0, in_slot = 0, rerr0 = 0, bad_n = 0, rejects = 0, skipped = 0;
    integer runs [0:15];            // go count per entry
    integer exp_runs [0:15];        // the model's: the cycles that ended in which the entry was valid and due
    integer wraps = 0, high_runs = 0;
    initial for (i = 0; i < 16; i = i + 1) begin runs[i] = 0; exp_runs[i] = 0; end
    always @(posedge clk) if (!rst) begin
        done <= 1'b0;
        if (errors >= 12) begin
            $display("FAIL %0d failures: the bench stops here", errors);
            $finish;
        end
        if (mreject) rejects = rejects + 1;
        if (cyc_s) begin
            if (cstart >= 0) begin
                // the cycle just ended: its length, no due entry left out, its invalid entries counted
                if (t - cstart != m_cycle[cur_mode]) begin
                    $display("FAIL cycle length %0d in mode %0d, expected %0d", t - cstart, cur_mode, m_cycle[cur_mode]);
                    errors = errors + 1;
                end
                bad_n = 0;
                for (j = m_first[cur_mode]; j < m_end[cur_mode]; j = j + 1) begin
                    if (!valid(j, cur_mode)) bad_n = bad_n + 1;
                    else if (due(j, n)) exp_runs[j] = exp_runs[j] + 1;
                    if (valid(j, cur_mode) && j >= k && due(j, n)) begin
                        $display("FAIL entry %0d (mode %0d) is due in minor cycle %0d and did not run", j, cur_mode, n);
                        errors = errors + 1;
                    end
                end
                if (rerr - rerr0 != bad_n) begin
                    $display("FAIL rom_errors grew by %0d in a cycle of mode %0d, expected %0d (its invalid entries)",
                             rerr - rerr0, cur_mode, bad_n);
                    errors = errors + 1;
                end
            end
            if (cstart < 0 || mode != cur_mode) n = 0;
            else begin
                n = (n + 1) % (1 << m_cl[cur_mode]);
                if (n == 0) wraps = wraps + 1;
            end
            cur_mode = mode; cstart = t; k = m_first[cur_mode]; t_free = t; rerr0 = rerr; cyc_n = cyc_n + 1;
        end
        if (go) begin
            // the next entry the model runs: skip those not due or invalid (each costs its fetch)
            j = k;
            s = 0;
            while (j < m_end[cur_mode] && !(valid(j, cur_mode) && due(j, n))) begin
                s = cstart + e_start[j] > t_free ? cstart + e_start[j] : t_free;
                t_free = s + 7;
                j = j + 1;
                skipped = skipped + 1;
            end
            if (j >= m_end[cur_mode]) begin
                $display("FAIL go at %0d (channel %0d) in minor cycle %0d of mode %0d: no entry is due there", t, chan, n,
                         cur_mode);
                errors = errors + 1;
            end else begin
                s = cstart + e_start[j] > t_free ? cstart + e_start[j] : t_free;
                if (t != s + 6 || slot_time != s || chan != e_chan[j] || kind != e_kind[j][1:0]) begin
                    $display("FAIL entry %0d (mode %0d, minor cycle %0d) go at %0d, slot time %0d, channel %0d, kind %0d; expected go at %0d, slot time %0d, channel %0d, kind %0d",
                             j, cur_mode, n, t, slot_time, chan, kind, s + 6, s, e_chan[j], e_kind[j]);
                    errors = errors + 1;
                end
                runs[j] = runs[j] + 1;
                cur = j; k = j + 1;
            end
            gos = gos + 1; in_slot = 1;
        end
        if (in_slot && may) last_may = t;
        if (in_slot && !may && !go) begin
            // the last access may go on the bus at last_may + 1 <= D - TIMEOUT - 2
            if (last_may + 1 != cstart + e_start[cur] + e_len[cur] - 10) begin
                $display("FAIL entry %0d last access clock %0d, expected %0d", cur, last_may + 1,
                         cstart + e_start[cur] + e_len[cur] - 10);
                errors = errors + 1;
            end
            in_slot = 0; done <= 1'b1; t_free = t + 2;      // done next clock; the sequencer waits from the one after
        end
    end

    initial begin
        repeat (3) @(posedge clk);
        rst = 0;
        if ($test$plusargs("modes")) begin
            // mode 0 for 13 cycles (the count then at 12), mode 1 for 12 (cluster 2: wraps three times), mode 0 again
            wait (cyc_n == 13); repeat (50) @(posedge clk);
            mreq <= 1; mreq_mode <= 4'd1; @(posedge clk); mreq <= 0;
            wait (cyc_n == 25); repeat (30) @(posedge clk);
            if (mode != 1) begin $display("FAIL expected mode 1 after its request, came %0d", mode); errors = errors + 1; end
            mreq <= 1; mreq_mode <= 4'd0; @(posedge clk); mreq <= 0;
            wait (cyc_n == 37); @(posedge clk);
            if (mode != 0 || rejects != 0) begin
                $display("FAIL expected mode 0 again and no rejection, came mode %0d, %0d rejections", mode, rejects);
                errors = errors + 1; end
        end else begin
            wait (cyc_n == 265); @(posedge clk);      // cluster 8: the count wraps once, the rep-8 entry runs twice
        end
        if (error || wraps < 1) begin
            $display("FAIL error %0d, the count wrapped %0d times (expected 1 or more)", error, wraps); errors = errors + 1;
        end
        for (i = 0; i < ne && i < 16; i = i + 1) begin
            $display("entry %0d: rep %0d base %0d: %0d runs", i, e_rep[i], e_base[i], runs[i]);
            if (runs[i] != exp_runs[i]) begin
                $display("FAIL entry %0d ran %0d times, expected %0d (the cycles n with n mod %0d = %0d it was due in)",
                         i, runs[i], exp_runs[i], 1 << e_rep[i], e_base[i] % (1 << e_rep[i]));
                errors = errors + 1;
            end
            if (e_base[i] >= (1 << e_rep[i])) begin
                $display("entry %0d: base %0d >= 2^rep = %0d ran in the %0d cycles with n mod %0d = %0d",
                         i, e_base[i], 1 << e_rep[i], runs[i], 1 << e_rep[i], e_base[i] % (1 << e_rep[i]));
                high_runs = high_runs + runs[i];
            end
        end
        if (high_runs == 0) begin
            $display("FAIL no entry with base >= 2^rep ran: expected the image's one to run (the due rule reads base mod 2^rep)");
            errors = errors + 1;
        end
        $display("%0d cycles, %0d slots, %0d entries skipped (not due or invalid), rom_errors %0d, %0d wraps of the count",
                 cyc_n - 1, gos, skipped, rerr, wraps);
        if (errors == 0) $display("PASS tb_sequencer_multirate");
        $finish;
    end
    initial begin                     // watchdog
        #5000000;
        $display("FAIL watchdog: the bench did not end (cycles %0d)", cyc_n);
        $finish;
    end
endmodule
`default_nettype wire
