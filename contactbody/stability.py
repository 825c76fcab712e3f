"""What the stability maps (examples/damped_stability.py, examples/rate_stability.py) read off
their measured growth rates; numpy-free, so that scripts/write_stability_map.py runs anywhere."""


def first_stable(grid, growth):
    """Smallest value of an ascending grid from which every larger one has growth < 0 (None
    if the largest grows, or if there is no steady state: growth None)."""
    if growth is None:
        return None
    stable = [g < 0 for g in growth]
    if not stable[-1]:
        return None
    k = len(stable) - 1
    while k > 0 and stable[k - 1]:
        k -= 1
    return float(grid[k])
