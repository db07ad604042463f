#!/usr/bin/env python3
"""Plays the sweep's manager/worker schedule (src/sweep/scheduler.cpp) with measured tile
costs, for any number of ranks: how well would R ranks be used?

The costs come from `build/benchmarks/tile_costs [sweep options] > costs.csv`: per tile, the
time a rank takes to compute and encode it, and the time rank 0 takes to journal and write
it. The simulation follows the scheduler's rules:
  - rank 0 hands out batches of about (tiles left) / (4 R) tiles (at least 1, at most 256),
    two batches in flight per worker, refilled whenever one of the worker's results is taken;
  - rank 0 takes results only between tiles of its own (each costing its sink time), and
    computes tiles itself while there are tiles to hand out;
  - a worker computes its tiles in order and sends each result at once (latency below).
Efficiency = (sum of compute times) / (R x makespan); speed-up = (one rank's time) / makespan.

Usage: scheduler_simulation.py costs.csv [--ranks 1,2,16,128,1024] [--latency 2e-5]
"""
from __future__ import annotations

import argparse
import csv
import heapq
from collections import deque

MAX_BATCH = 256
BATCHES_IN_FLIGHT = 2


def simulate(compute: list[float], sink: list[float], ranks: int, latency: float) -> float:
    """The makespan of the schedule on `ranks` ranks, in seconds."""
    tiles = deque(range(len(compute)))
    if ranks == 1:
        return sum(compute) + sum(sink)
    workers = range(1, ranks)
    backlog = {w: deque() for w in workers}  # tiles handed to a worker, not yet started
    busy_until = {w: 0.0 for w in workers}
    outstanding = {w: 0 for w in workers}
    arrivals: list[tuple[float, int, int]] = []  # (time the result reaches rank 0, worker, tile)

    def guided() -> int:
        return max(1, min(MAX_BATCH, len(tiles) // (4 * ranks)))

    def start_work(w: int, now: float) -> None:
        # The worker runs its backlog back to back from when a batch reaches it.
        t = max(busy_until[w], now)
        while backlog[w]:
            tile = backlog[w].popleft()
            t += compute[tile]
            heapq.heappush(arrivals, (t + latency, w, tile))
        busy_until[w] = t

    def send_batch(w: int, now: float) -> None:
        n = guided()
        for _ in range(min(n, len(tiles))):
            backlog[w].append(tiles.popleft())
        outstanding[w] += n
        start_work(w, now + latency)

    clock = 0.0
    for w in workers:
        for _ in range(BATCHES_IN_FLIGHT):
            if tiles:
                send_batch(w, clock)
    done = 0
    total = len(compute)
    while done < total:
        # Take every result that has arrived, refilling the senders' batches.
        while arrivals and arrivals[0][0] <= clock:
            _, w, tile = heapq.heappop(arrivals)
            clock += sink[tile]
            done += 1
            outstanding[w] -= 1
            while tiles and outstanding[w] < BATCHES_IN_FLIGHT * guided():
                send_batch(w, clock)
        if done == total:
            break
        if tiles:
            tile = tiles.popleft()
            clock += compute[tile] + sink[tile]
            done += 1
        elif arrivals:
            clock = max(clock, arrivals[0][0])
    return clock


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("costs", help="CSV from build/benchmarks/tile_costs")
    parser.add_argument("--ranks", default="1,2,16,128,1024", help="comma-separated rank counts")
    parser.add_argument("--latency", type=float, default=2e-5, help="message latency, s (default 2e-5)")
    args = parser.parse_args()
    with open(args.costs) as f:
        rows = list(csv.DictReader(f))
    compute = [float(r["compute_s"]) for r in rows]
    sink = [float(r["sink_s"]) for r in rows]
    one = sum(compute) + sum(sink)
    print(f"{len(rows)} tiles, {sum(int(r['points']) for r in rows)} points: compute {sum(compute):.3g} s, "
          f"rank 0's journal and writes {sum(sink):.3g} s (one rank: {one:.3g} s)")
    print(f"{'ranks':>6} {'makespan s':>11} {'speed-up':>9} {'efficiency':>10}")
    for ranks in [int(r) for r in args.ranks.split(",")]:
        makespan = simulate(compute, sink, ranks, args.latency)
        print(f"{ranks:>6} {makespan:>11.4g} {one / makespan:>9.3g} {sum(compute) / (ranks * makespan):>10.1%}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
