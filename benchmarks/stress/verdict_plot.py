"""The verdict counts per group as stacked horizontal bars (PNG), for
run.py (stress.png) and bad_input.py (bad_input.png). matplotlib is
optional: both scripts need only the standard library."""


def stacked_verdict_bars(path, pairs, colours, unit, title):
    """pairs: (group, verdict) per run; colours: verdict -> colour, in the
    order of the bars; unit: the x axis label."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print(f"matplotlib missing: no {path}")
        return
    groups = list(dict.fromkeys(group for group, _ in pairs))
    figure, axis = plt.subplots(figsize=(8, 0.4 * len(groups) + 1.5))
    left = [0] * len(groups)
    for verdict, colour in colours.items():
        counts = [sum(1 for g, v in pairs if g == group and v == verdict)
                  for group in groups]
        if any(counts):
            axis.barh(groups, counts, left=left, color=colour,
                      label=f"{verdict} ({sum(counts)})")
            left = [a + b for a, b in zip(left, counts)]
    axis.invert_yaxis()
    axis.set_xlabel(unit)
    axis.set_title(title, fontsize=10)
    axis.legend(fontsize=8, loc="lower right")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)
