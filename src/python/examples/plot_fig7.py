"""The seed's Fig. 7 with matplotlib: mu_macro/mu0 of the paraboloid against
vbar for du/u0 = 0, 0.2, ..., 1, exact, in one broadcast call.

    python src/python/examples/plot_fig7.py [out.png]

"""

from __future__ import annotations

import sys

import numpy as np

import fricosc


def main(out: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    vbar = np.linspace(0.0, 1.2, 241)
    amps = np.array([0.0, 0.2, 0.4, 0.6, 0.8, 1.0])
    # One call for the whole family: vbar down the rows, amp across the columns.
    mu = np.asarray(fricosc.mu_ratio("parabolic", vbar[:, None], amps[None, :]))
    fig, ax = plt.subplots(figsize=(3.35, 2.6), dpi=200)  # 8.5 cm: one journal column
    colours = plt.get_cmap("viridis")(np.linspace(0.0, 0.85, len(amps)))
    for j, a in enumerate(amps):
        ax.plot(vbar, mu[:, j], color=colours[j], lw=2.0 if a == 1.0 else 1.0, label=f"{a:g}")
    ax.set_xlabel(r"$\bar v$ (eq. 3)")
    ax.set_ylabel(r"$\mu_{macro}/\mu_0$")
    ax.set_xlim(0.0, 1.2)
    ax.set_ylim(0.0, 1.02)
    ax.legend(title=r"$\Delta u_z/u_{z0}$", fontsize=6, title_fontsize=6, frameon=False, loc="lower right")
    ax.set_title("Fig. 7: paraboloid (exact)", fontsize=8)
    fig.tight_layout()
    fig.savefig(out)
    print(f"wrote {out}: mu/mu0 at vbar = 0.5 for du/u0 = 0.4: {mu[100, 2]:.15f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "fig7.png")
