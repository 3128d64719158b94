"""FishEnv steps per second: python3 -m urwpgsim2d.benchmark [EPISODES] (median over episodes of 1,000 steps, polo-1v1 against chase-ball)."""

import statistics
import sys
import time

from .env import FishEnv


def main(episodes: int = 5) -> None:
    env = FishEnv(item="polo-1v1", opponent="chase-ball", cycles=6000)
    rates = []
    for seed in range(episodes):
        env.reset(seed=seed, options={"max_steps": 1000})
        start = time.perf_counter()
        steps = 0
        while True:
            _, _, terminated, truncated, _ = env.step([12, 7])
            steps += 1
            if terminated or truncated:
                break
        rates.append(steps / (time.perf_counter() - start))
    env.close()
    print("FishEnv: %.0f steps/s (median of %d episodes of %d steps; min %.0f, max %.0f)" % (statistics.median(rates), episodes, 1000, min(rates), max(rates)))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 5)
