/*
 * mobot_navigation.c -- board 'navigation' of the four-board PicoRV32 system
 * (sim/pico_boards.v): imports RadarMap, Position, GlobalTime and Status,
 * exports MotorCmd, through the compiler-generated navigation.c.  Reports 0
 * after MOBOT_NEWS New values of every copied import and MOBOT_EXPORTS
 * exports, then keeps going.  STAT: 0 RadarMap New, 1 Position New,
 * 2 GlobalTime New, 3 exports.  Checks and events: sim/firmware/mobot_check.h.
 *
 * Actuality, by the sampling read (alb_read,
 * docs/protocol.md "Sampling read"): ReadRadarMap ages the map as now -
 * taken_at, where now is the global time read BEFORE the Import (the clock's
 * estimate when the board runs one, else the GlobalTime value of the loop
 * before), so the age never exceeds the map's true age at the Import,
 * whatever the core does between.  A healthy radar ends an Export at least
 * every MOBOT_RADAR_SCAN_CLOCKS and the controller publishes an Export here
 * within ALB_RADARMAP_LATENCY_CLOCKS, so the newest map here is never older
 * than ALB_RADARMAP_MAX_AGE_CLOCKS(MOBOT_RADAR_SCAN_CLOCKS); now leads the
 * controller's time by at most MOBOT_NOW_LEAD_CLOCKS.  A map older than the
 * two (status STALE) means the radar stopped: navigation reports
 * MOBOT_EV_STALE (and MOBOT_EV_FRESH when fresh maps come back) and keeps
 * driving on the last one.  Before the first New map the status is NEVER.
 *
 * Schedule modes: built against a description with the modes cruise and dock
 * (ALB_MODE_DOCK defined, sim/mobot3_modes.toml), navigation also imports
 * Mode (reporting every New one as MOBOT_EV_MODE) and exports ModeRequest:
 * dock after a stay in cruise, cruise after a stay in dock (mobot_check.h:
 * MOBOT_CRUISE_CLOCKS, MOBOT_DOCK_CLOCKS, each plus a pseudo-random part),
 * again after MOBOT_MODE_RETRY_CLOCKS if the mode did not change.  In
 * dock the controller carries no RadarMap and no Status: the map goes STALE
 * and comes back FRESH in cruise, as after a radar crash.
 *
 * Slow channels (sim/mobot3_slow.toml: ALB_RADARSCAN_ID, ALB_NAVLOG_ID
 * defined): navigation imports and checks the radar's full scan RadarScan
 * every MOBOT_SLOW_EVERY-th loop and exports its log NavLog at the start and
 * then every MOBOT_LOG_PERIOD_CLOCKS (by now); it reports 0 only after
 * MOBOT_SCAN_NEWS New scans too.  Both run in cruise only.
 */
#include "albatross.h"
#include "navigation.h"
#include "mobot_check.h"

#define NAV_RADAR_STALE_CLOCKS (ALB_RADARMAP_MAX_AGE_CLOCKS(MOBOT_RADAR_SCAN_CLOCKS) + MOBOT_NOW_LEAD_CLOCKS)

/* Retries and abandoned transfers summed over the channels of the system. */
static void nav_status_event(const Status_t *s)
{
    uint32_t id, retries = 0u, abandoned = 0u;
    for (id = 0u; id <= ALB_STATUS_ID; ++id) {
        retries += ALB_STATUS_RETRIES(s->word, id);
        abandoned += ALB_STATUS_ABANDONED(s->word, id);
    }
    mobot_event(MOBOT_EV_STATUS, ALB_STATUS_ID, abandoned, retries);
}

int main(void)
{
    static RadarMap_msg map;
    static Position_msg pos;
    static GlobalTime_msg gt;
    static mobot_clock_t clk;
    static Status_msg st;
    static MotorCommand cmd;
    mobot_track_t tr = {0u, 0u, 0u, 0u}, tp = {0u, 0u, 0u, 0u}, tt = {0u, 0u, 0u, 0u};
    alb_sample_t smp;
    uint32_t seq = 0u, code, reported = 0u, stale = 0u, now;
    int r;
#ifdef ALB_RADARSCAN_ID
    static RadarScan_msg scan;
    mobot_track_t ts = {0u, 0u, 0u, 0u};
#endif
#ifdef ALB_NAVLOG_ID
    static NavLogData log;
    uint32_t log_seq = 0u, log_at = 0u;
#endif
#ifdef ALB_MODE_DOCK
    static Mode_msg md;            /* the running mode (the RAM image's: cruise, since 0) */
    uint32_t want = ALB_MODE_CRUISE, asked_at = 0u, asks = 0u, switches = 0u, stay = MOBOT_CRUISE_CLOCKS;
#endif

#ifdef MOBOT_COLD_START
    r = alb_navigation_init_all(BOARD_DPRAM_BASE);     /* a zeroed RAM, no image */
#else
    r = alb_navigation_attach_all(BOARD_DPRAM_BASE);
#endif
    if (r != ALB_OK)
        return (int)MOBOT_CODE(2, 0xfu, (uint32_t)-r);
    mobot_clock_init(&clk);
    for (;;) {
        mobot_clock_report(&clk);
        now = mobot_now(&clk, gt.value);   /* before the map's Import */
        r = mobot_read(&alb_ch_RadarMap, ALB_RADARMAP_ID, &map, &map.taken_at, NAV_RADAR_STALE_CLOCKS, now, &smp);
        code = mobot_check(&tr, ALB_RADARMAP_ID, r, radar_ok0(&map.value), radar_seq(&map.value));
        if (code)
            return (int)code;
        r = mobot_import(&alb_ch_Position, ALB_POSITION_ID, &pos, &pos.taken_at);
        code = mobot_check(&tp, ALB_POSITION_ID, r, position_ok0(&pos.value), (uint32_t)pos.value.x_mm);
        if (code)
            return (int)code;
        r = mobot_import(&alb_ch_GlobalTime, ALB_GLOBALTIME_ID, &gt, &gt.taken_at);
        mobot_clock_sync(&clk, r, gt.taken_at);
        code = mobot_check(&tt, ALB_GLOBALTIME_ID, r, 1, gt.value);
        if (code)
            return (int)code;
        if (!stale && smp.status == ALB_SAMPLE_STALE) {
            mobot_event(MOBOT_EV_STALE, ALB_RADARMAP_ID, 0u, smp.age_clocks);
            stale = 1u;
        } else if (stale && (smp.status == ALB_SAMPLE_NEW || smp.status == ALB_SAMPLE_OLD)) {
            mobot_event(MOBOT_EV_FRESH, ALB_RADARMAP_ID, 0u, smp.age_clocks);
            stale = 0u;
        }
        r = mobot_import(&alb_ch_Status, ALB_STATUS_ID, &st, &st.taken_at);
        if (r != ALB_NEW && r != ALB_OLD)
            return (int)MOBOT_CODE(1, ALB_STATUS_ID, 0u);
        if (r == ALB_NEW)
            nav_status_event(&st.value);
#ifdef ALB_MODE_DOCK
        r = mobot_import(&alb_ch_Mode, ALB_MODE_ID, &md, &md.taken_at);
        if (r != ALB_NEW && r != ALB_OLD)
            return (int)MOBOT_CODE(1, ALB_MODE_ID, 0u);
        if (r == ALB_NEW) {
            mobot_event(MOBOT_EV_MODE, md.value.mode, 0u, md.value.since);
            stay = (md.value.mode == ALB_MODE_DOCK ? MOBOT_DOCK_CLOCKS : MOBOT_CRUISE_CLOCKS) +
                   (mobot_mix(++switches) & (MOBOT_MODE_SPREAD_CLOCKS - 1u));
        }
        /* signed: now (read before these Imports) may be older than since */
        if (want == md.value.mode && (int32_t)(now - md.value.since) >= (int32_t)stay)
            want = md.value.mode == ALB_MODE_DOCK ? ALB_MODE_CRUISE : ALB_MODE_DOCK;
        if (want != md.value.mode && (asks == 0u || (int32_t)(now - asked_at) >= (int32_t)MOBOT_MODE_RETRY_CLOCKS)) {
            if (mobot_export(&alb_ch_ModeRequest, ALB_MODEREQUEST_ID, &want, ++asks) != ALB_OK)
                return (int)MOBOT_CODE(7, ALB_MODEREQUEST_ID, asks);
            asked_at = now;
        } else if (want == md.value.mode) {
            asks = 0u;
        }
#endif
#ifdef ALB_RADARSCAN_ID
        if ((seq & (MOBOT_SLOW_EVERY - 1u)) == 0u) {
            r = mobot_import(&alb_ch_RadarScan, ALB_RADARSCAN_ID, &scan, &scan.taken_at);
            code = mobot_check(&ts, ALB_RADARSCAN_ID, r,
                               slow_ok0(scan.value.word, ALB_RADARSCAN_WORDS, MOBOT_SCAN_SHIFT),
                               slow_seq(scan.value.word, MOBOT_SCAN_SHIFT));
            if (code)
                return (int)code;
        }
#endif
#ifdef ALB_NAVLOG_ID
        if (log_seq == 0u || now - log_at >= MOBOT_LOG_PERIOD_CLOCKS) {
            log_at = now;
            slow_make(log.word, ALB_NAVLOG_WORDS, MOBOT_LOG_SHIFT, ++log_seq);
            if (mobot_export(&alb_ch_NavLog, ALB_NAVLOG_ID, &log, log_seq) != ALB_OK)
                return (int)MOBOT_CODE(7, ALB_NAVLOG_ID, log_seq);
        }
#endif
        motor_make(&cmd, ++seq);
        if (mobot_export(&alb_ch_MotorCmd, ALB_MOTORCMD_ID, &cmd, seq) != ALB_OK)
            return (int)MOBOT_CODE(7, ALB_MOTORCMD_ID, seq);
        if (!reported && seq >= MOBOT_EXPORTS && tr.news >= MOBOT_NEWS && tp.news >= MOBOT_NEWS &&
            tt.news >= MOBOT_NEWS
#ifdef ALB_RADARSCAN_ID
            && ts.news >= MOBOT_SCAN_NEWS
#endif
            ) {
            board_stat(0u, tr.news);
            board_stat(1u, tp.news);
            board_stat(2u, tt.news);
            board_stat(3u, seq);
            mobot_tohost(0u);
            reported = 1u;
        }
    }
}
