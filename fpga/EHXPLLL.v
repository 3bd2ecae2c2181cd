// EHXPLLL -- simulation and lint model of the ECP5 PLL primitive, for the
// parts of it fpga/ulx3s_top.v uses (Verilator and Icarus have no model of
// their own; Yosys and nextpnr use the real primitive, never this file).
// Rules:
//   * Time is scaled so that one CLKI period of the simulation is one CLKOP
//     period: CLKOP follows CLKI.  The simulation keeps the PLL's frequency
//     ratio, not its frequencies.
//   * CLKOS runs CLKOS_DIV / CLKOP_DIV times slower than CLKOP (both divide
//     the same VCO), from a counter on CLKI; that ratio must be a whole
//     number, 1 or even (elaboration stops otherwise).
//   * LOCK rises after LOCK_CLOCKS CLKI clocks and stays high.
//   * With the plusarg +pll_drift=SEED, CLKOS instead wanders: each of its
//     half-periods lasts 1 to 4 half-periods of CLKI, drawn from an LFSR
//     seeded with SEED, so its edges fall on either edge of CLKI and its
//     frequency moves between 1 and 1/4 of CLKOP's.  The two clocks are then
//     unrelated, as albatross_wb_cdc allows (an adversarial test, not a PLL).
// Port names are Lattice's; only the ports the top connects are modelled.
`default_nettype none

module EHXPLLL #(
    parameter CLKI_DIV     = 1,          // reference divider (VCO = CLKI * CLKFB_DIV / CLKI_DIV * CLKOP_DIV)
    parameter CLKFB_DIV    = 1,          // feedback divider
    parameter CLKOP_DIV    = 8,          // VCO / CLKOP
    parameter CLKOP_CPHASE = 0,          // CLKOP coarse phase (not modelled)
    parameter CLKOS_ENABLE = "DISABLED", // "ENABLED": CLKOS runs
    parameter CLKOS_DIV    = 8,          // VCO / CLKOS
    parameter CLKOS_CPHASE = 0,          // CLKOS coarse phase (not modelled)
    parameter FEEDBK_PATH  = "CLKOP",    // feedback from CLKOP (the only path modelled)
    parameter LOCK_CLOCKS  = 16          // model only: CLKI clocks until LOCK
) (
    input  wire CLKI,
    input  wire CLKFB,
    input  wire RST,
    input  wire STDBY,
    input  wire PHASESEL0,
    input  wire PHASESEL1,
    input  wire PHASEDIR,
    input  wire PHASESTEP,
    input  wire PHASELOADREG,
    input  wire PLLWAKESYNC,
    input  wire ENCLKOP,
    output wire CLKOP,
    output wire CLKOS,
    output wire LOCK
);

    localparam        RATIO = CLKOS_DIV / CLKOP_DIV;  // CLKOS period in CLKOP periods
    localparam [31:0] LAST  = RATIO - 1;              // the divider's last count
    localparam [31:0] HALF  = RATIO / 2;              // counts with CLKOS high

    generate
        if (CLKOS_DIV % CLKOP_DIV != 0 || (RATIO != 1 && RATIO % 2 != 0) || FEEDBK_PATH != "CLKOP"
            || CLKOS_ENABLE != "ENABLED") begin : g_check
            EHXPLLL_model_needs_CLKOS_enabled_at_1_or_an_even_multiple_of_CLKOP_fed_back_from_CLKOP u_error ();
        end
    endgenerate

    reg [7:0] lock_q = 8'd0;   // CLKI clocks seen, up to LOCK_CLOCKS
    reg [7:0] div_q  = 8'd0;   // position in the CLKOS period
    reg       clkos_q = 1'b0;

    always @(posedge CLKI) begin
        if (lock_q != LOCK_CLOCKS[7:0]) lock_q <= lock_q + 8'd1;
        div_q   <= (div_q == LAST[7:0]) ? 8'd0 : div_q + 8'd1;
        clkos_q <= (div_q < HALF[7:0]);
    end

    // +pll_drift=SEED: CLKOS from random half-periods on both edges of CLKI.
    reg        drift   = 1'b0;      // the plusarg was given
    reg [15:0] lfsr_q  = 16'hace1;  // x^16 + x^14 + x^13 + x^11 + 1
    reg [2:0]  left_q  = 3'd1;      // CLKI half-periods left in this CLKOS half-period
    reg        drift_q = 1'b0;      // the wandering CLKOS
    reg [15:0] seed;
    initial begin
        if ($value$plusargs("pll_drift=%d", seed)) begin
            drift  = 1'b1;
            lfsr_q = seed | 16'h0001;   // never the all-zero state
        end
    end
    always @(posedge CLKI or negedge CLKI) begin
        if (left_q == 3'd1) begin
            drift_q <= ~drift_q;
            left_q  <= {1'b0, lfsr_q[1:0]} + 3'd1;
            lfsr_q  <= {lfsr_q[14:0], lfsr_q[15] ^ lfsr_q[13] ^ lfsr_q[12] ^ lfsr_q[10]};
        end else begin
            left_q  <= left_q - 3'd1;
        end
    end

    assign CLKOP = CLKI;
    assign CLKOS = drift ? drift_q : (RATIO == 1) ? CLKI : clkos_q;
    assign LOCK  = (lock_q == LOCK_CLOCKS[7:0]);

    wire unused = &{1'b0, CLKFB, RST, STDBY, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP, PHASELOADREG,
                    PLLWAKESYNC, ENCLKOP, CLKI_DIV[0], CLKFB_DIV[0], CLKOP_CPHASE[0], CLKOS_CPHASE[0]};

endmodule

`default_nettype wire
