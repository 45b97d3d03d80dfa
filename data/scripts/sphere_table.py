"""The tabulated sphere of the examples and the suite, data/profiles/sphere.csv:
a sphere of radius 1, f(r) = 1 - sqrt(1 - r^2), at r = 0, 5e-5, ..., 0.01.

Each f is the correctly rounded double of r^2 / (1 + sqrt(1 - r^2)) evaluated in
40-digit arithmetic at the double r (the naive 1 - sqrt(1 - r^2) in doubles
loses up to 1.4e-8 of f near the axis, where the two terms cancel).

Run: python3 data/scripts/sphere_table.py > data/profiles/sphere.csv   (needs mpmath)
"""
from decimal import Decimal
from mpmath import mp, mpf, sqrt

mp.dps = 40
print("# sphere of radius 1 (f = R - sqrt(R^2 - r^2) = r^2/(R + sqrt(R^2 - r^2))), 201 points, correctly rounded;")
print("# use with a small mean indentation, e.g. @1e-6 (data/scripts/sphere_table.py)")
print("r,f")
for i in range(201):
    r = float(Decimal(i) * Decimal("5e-5"))
    x = mpf(r)
    f = float(x * x / (1 + sqrt(1 - x * x)))
    print(f"{r!r},{f!r}")
