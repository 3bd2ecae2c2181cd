"""schedulability_gen.py -- the system generator of the schedulability
benchmark (tools/schedulability_bench.py, which documents the systems):
each system description made from its seed alone."""
import json
import math
import random

from albatross_schedule import ScheduleError, parse_description
from albatross_schedule.description import MAX_RAM_BYTES
from albatross_schedule.layout import allocate_ram
from albatross_schedule.model import Bus, Channel
from albatross_schedule.plan import slot_length

CLOCK_HZ = 50_000_000
SEED_STRIDE = 10_000            # seed = target percent * SEED_STRIDE + counter
PERIOD_US = (50, 50_000)        # log-uniform, three decades
SIZE_BYTES = (4, 2048)          # log-uniform
BOARDS = (2, 16)
CHANNELS = (4, 64)              # log-uniform
CONSUMERS = ((1, 0.5), (2, 0.25), (3, 0.15), (4, 0.1))   # (count, weight), capped at boards - 1
TOLERANCE = 0.005               # |demand - target| at most half a percentage point


class Redraw(Exception):
    """This seed gives no system at its target: take the next one."""

    def __init__(self, kind, detail):
        super().__init__(detail)
        self.kind = kind


def target_of(seed: int) -> int:
    return seed // SEED_STRIDE


def _length(words: int, consumers: int, bus: Bus) -> int:
    """The compiler's slot length of a copy channel (plan.slot_length)."""
    ch = Channel(index=0, name="x", kind="copy", ctype=None, size=4 * words, words=words, producer=0,
                 consumers=list(range(1, consumers + 1)), max_period_us=1)
    return slot_length(ch, bus)


def system_demand(system) -> float:
    return sum(slot_length(ch, system.bus) / ch.period_clocks for ch in system.channels)


def generate(seed: int) -> tuple:
    """(description dict, facts) of the system of this seed, or Redraw."""
    target = target_of(seed) / 100.0
    if not 0 < target < 10:
        raise ValueError(f"seed {seed}: its demand target {target_of(seed)} % (seed // {SEED_STRIDE}) is not in 1..999")
    rng = random.Random(seed)
    nb = rng.randint(*BOARDS)
    nc = int(round(math.exp(rng.uniform(math.log(CHANNELS[0]), math.log(CHANNELS[1])))))
    lp = (math.log(PERIOD_US[0]), math.log(PERIOD_US[1]))
    ls = (math.log(SIZE_BYTES[0]), math.log(SIZE_BYTES[1]))
    chans = []
    for _ in range(nc):
        prod = rng.randrange(nb)
        nd = rng.choices([c for c, _ in CONSUMERS], [w for _, w in CONSUMERS])[0]
        nd = min(nd, nb - 1)
        cons = sorted(rng.sample([b for b in range(nb) if b != prod], nd))
        chans.append({"prod": prod, "cons": cons, "period": math.exp(rng.uniform(*lp)),
                      "size": math.exp(rng.uniform(*ls))})
    bus = Bus()
    lmin = [_length(1, len(c["cons"]), bus) for c in chans]
    lmax = [_length(SIZE_BYTES[1] // 4, len(c["cons"]), bus) for c in chans]

    def periods(h):
        return [max(PERIOD_US[0], int(round(c["period"] * h))) if h >= 1 else int(round(c["period"] * h))
                for c in chans]

    def words(g):
        return [min(SIZE_BYTES[1] // 4, max(1, int(round(c["size"] * g / 4)))) for c in chans]

    def demand(ws, ps):
        return sum(_length(w, len(c["cons"]), bus) / (p * CLOCK_HZ // 1_000_000)
                   for w, c, p in zip(ws, chans, ps))

    # The periods: stretched when 4-byte values already exceed the target
    # (leaving a quarter of it to the sizes), shrunk (to a shortest period of
    # 50 us at most) when 2 KB values cannot reach it.
    h = 1.0
    ps = periods(h)
    lo = sum(l / (p * CLOCK_HZ // 1_000_000) for l, p in zip(lmin, ps))
    hi = sum(l / (p * CLOCK_HZ // 1_000_000) for l, p in zip(lmax, ps))
    if lo * 1.25 > target:
        h = lo * 1.25 / target
    elif hi < target * 1.1:
        h = max(PERIOD_US[0] / min(c["period"] for c in chans), hi / (target * 1.1))
    ps = periods(h)
    if min(ps) < PERIOD_US[0]:
        raise AssertionError(f"seed {seed}: period {min(ps)} us below {PERIOD_US[0]}")
    hi = sum(l / (p * CLOCK_HZ // 1_000_000) for l, p in zip(lmax, ps))
    if hi < target:
        raise Redraw("unreachable", f"2 KB values give {100 * hi:.1f} % < {100 * target:g} %")
    # The sizes: one factor for all, bisected on a log scale.
    glo, ghi = -8.0, math.log(SIZE_BYTES[1] * 4.0)
    for _ in range(60):
        mid = (glo + ghi) / 2
        if demand(words(math.exp(mid)), ps) <= target:
            glo = mid
        else:
            ghi = mid
    best = min((words(math.exp(glo)), words(math.exp(ghi))), key=lambda ws: abs(demand(ws, ps) - target))
    d = demand(best, ps)
    if abs(d - target) > TOLERANCE:
        raise Redraw("off-target", f"sizes reach {100 * d:.2f} %, not {100 * target:g} %")
    boards = [f"b{i}" for i in range(nb)]
    data = {"system": {"name": f"sched_{seed}", "clock_hz": CLOCK_HZ, "boards": boards,
                       "ram_bytes": MAX_RAM_BYTES},
            "bus": {"n_chan": max(16, nc)},
            "channel": [{"name": f"c{i}", "size": 4 * w, "producer": boards[c["prod"]],
                         "consumers": [boards[b] for b in c["cons"]], "max_period_us": p}
                        for i, (c, w, p) in enumerate(zip(chans, best, ps))]}
    system = parse_description(json.loads(json.dumps(data)), f"<seed {seed}>")
    d = system_demand(system)
    if abs(d - target) > TOLERANCE:
        raise AssertionError(f"seed {seed}: the compiler's demand {d:.4f} is not the generator's")
    try:
        allocate_ram(system)
    except ScheduleError as e:
        raise Redraw("ram-overflow", e.messages[0].split(": ", 1)[-1][:200])
    facts = {"seed": seed, "target_pct": target_of(seed), "demand": round(d, 5), "boards": nb, "channels": nc,
             "period_us": [min(ps), max(ps)], "value_bytes": [4 * min(best), 4 * max(best)],
             "period_stretch": round(h, 4)}
    return data, facts


def draw_level(level: int, count: int) -> tuple:
    """The first `count` systems of a demand level: [(data, facts)] and the
    redraws {kind: [seeds]}."""
    out, redraws = [], {"ram-overflow": [], "unreachable": [], "off-target": []}
    k = 0
    while len(out) < count:
        if k >= SEED_STRIDE:
            raise SystemExit(f"schedulability: level {level} %: no {count} systems within {SEED_STRIDE} seeds")
        seed = level * SEED_STRIDE + k
        k += 1
        try:
            out.append(generate(seed))
        except Redraw as r:
            redraws[r.kind].append(seed)
    return out, redraws


def toml_text(data: dict, comment: str = "") -> str:
    """The description as a TOML file (the generator's few value types)."""
    def val(v):
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, list):
            return "[" + ", ".join(val(x) for x in v) + "]"
        return str(v)
    lines = [f"# {ln}" for ln in comment.splitlines()]
    for sect in ("system", "bus"):
        lines += ["", f"[{sect}]"] + [f"{k} = {val(v)}" for k, v in data[sect].items()]
    for ch in data["channel"]:
        lines += ["", "[[channel]]"] + [f"{k} = {val(v)}" for k, v in ch.items()]
    return "\n".join(lines).lstrip("\n") + "\n"
