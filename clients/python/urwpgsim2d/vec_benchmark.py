"""FishVecEnv against FishEnv, in one run: python3 -m urwpgsim2d.vec_benchmark [NUM_ENVS] [STEPS]

polo-1v1 against chase-ball, the team swimming ahead (action 12, 7). FishEnv: the median of 5
episodes of 1,000 steps over TCP with a server process. FishVecEnv: NUM_ENVS (64) matches stepped
STEPS (3,000) times after 100 warm-up steps, this process pinned to one core (the native library
runs on the calling thread), both per second of wall time and per second of that thread's CPU time
(what the core gives when nothing else runs on it). Memory per env: the growth of this process's
resident memory when 1,024 matches are created and reset, divided by 1,024.
"""

import os
import statistics
import sys
import time

import numpy as np

from .env import FishEnv
from .vec import FishVecEnv


def fishenv_rate(episodes: int = 5, steps: int = 1000) -> float:
    env = FishEnv(item="polo-1v1", opponent="chase-ball", cycles=6000)
    rates = []
    try:
        for seed in range(episodes):
            env.reset(seed=seed, options={"max_steps": steps})
            start = time.perf_counter()
            n = 0
            while True:
                _, _, terminated, truncated, _ = env.step([12, 7])
                n += 1
                if terminated or truncated:
                    break
            rates.append(n / (time.perf_counter() - start))
    finally:
        env.close()
    return statistics.median(rates)


def vec_rate(num_envs: int, steps: int):
    """(env-steps per wall second, env-steps per CPU second of the stepping thread)."""
    env = FishVecEnv("polo-1v1", "chase-ball", num_envs=num_envs, cycles=6000)
    try:
        env.reset(seed=0)
        actions = np.tile(np.array([12, 7]), (num_envs, 1))
        for _ in range(100):
            env.step(actions)
        start, cpu = time.perf_counter(), time.thread_time()
        for _ in range(steps):
            env.step(actions)
        wall, cpu = time.perf_counter() - start, time.thread_time() - cpu
        return num_envs * steps / wall, num_envs * steps / cpu
    finally:
        env.close()


def resident_bytes() -> int:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def memory_per_env(count: int = 1024) -> float:
    # A first batch loads the library and runs its code once, so the measure is of matches only.
    warm = FishVecEnv("polo-1v1", "chase-ball", num_envs=8)
    warm.reset(seed=0)
    warm.close()
    before = resident_bytes()
    env = FishVecEnv("polo-1v1", "chase-ball", num_envs=count)
    env.reset(seed=0)
    grown = resident_bytes() - before
    env.close()
    return grown / count


def main(num_envs: int = 64, steps: int = 3000) -> None:
    fish_env = fishenv_rate()
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {sorted(os.sched_getaffinity(0))[0]})
    vec, vec_cpu = vec_rate(num_envs, steps)
    memory = memory_per_env()
    print("| environment | env-steps/s |")
    print("|---|---|")
    print("| FishEnv (TCP, server process) | %.0f |" % fish_env)
    print("| FishVecEnv, %d envs, one core | %.0f (%.0f per CPU second) |" % (num_envs, vec, vec_cpu))
    print()
    print("FishVecEnv / FishEnv: %.1fx; memory per env after reset: %.1f KB; load average %.1f" % (vec / fish_env, memory / 1024, os.getloadavg()[0]))


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:3]))
