"""40-digit MDR transform g(x) = x int_0^x f'(r)/sqrt(x^2 - r^2) dr of a rough
tabulated profile, at a few knots, for src/fricosc/src/contact/profile/tests.rs.

The table uses only rational operations, so that Rust rebuilds it bit for bit:
r_0 = 0, r_i = i + ((7 i) mod 11)/13; f_0 = 0, f_i = f_(i-1) + ((5 i) mod 17)/19
(some steps are 0: flat pieces beside steep ones). The interpolant's slopes are
computed exactly as `Pchip::new` does (three-point slopes, Hyman's limiter, the
one-sided end slopes), in IEEE double like Rust; the integrals over each
interval's cubic are then done in 40-digit arithmetic in the angle t
(r = x sin t), where the integrand is smooth.

Usage: python3 data/scripts/mdr_transform_rough.py
"""
import mpmath as m

m.mp.dps = 40
N = 60
xs = [0.0] + [i + ((7 * i) % 11) / 13 for i in range(1, N)]
ys = [0.0]
for i in range(1, N):
    ys.append(ys[-1] + ((5 * i) % 17) / 19)

h = [xs[i + 1] - xs[i] for i in range(N - 1)]
de = [(ys[i + 1] - ys[i]) / h[i] for i in range(N - 1)]
d = [0.0] * N
for i in range(1, N - 1):
    if de[i - 1] * de[i] > 0.0:
        p = (h[i] * de[i - 1] + h[i - 1] * de[i]) / (h[i - 1] + h[i])
        lim = 3.0 * min(abs(de[i - 1]), abs(de[i]))
        d[i] = (1.0 if p > 0 else -1.0) * min(abs(p), lim)


def sign(v):
    # f64::signum: +1 for +0.0 and positive values, -1 for negative.
    return -1.0 if v < 0 else 1.0


def end(h0, h1, d0, d1):
    s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1)
    if sign(s) != sign(d0):
        return 0.0
    if sign(d0) != sign(d1) and abs(s) > 3.0 * abs(d0):
        return 3.0 * d0
    return s


d[0] = end(h[0], h[1], de[0], de[1])
d[N - 1] = end(h[N - 2], h[N - 3], de[N - 2], de[N - 3])


def g(j):
    x = m.mpf(xs[j])
    total = m.mpf(0)
    for i in range(j):
        x0, hh = m.mpf(xs[i]), m.mpf(xs[i + 1]) - m.mpf(xs[i])
        dy = m.mpf(ys[i + 1]) - m.mpf(ys[i])
        d0, d1 = m.mpf(d[i]) * hh, m.mpf(d[i + 1]) * hh

        def fprime(t):
            u = (x * m.sin(t) - x0) / hh
            return (6 * u * (1 - u) * dy + (3 * u * u - 4 * u + 1) * d0 + (3 * u * u - 2 * u) * d1) / hh

        total += m.quad(fprime, [m.asin(x0 / x), m.asin(m.mpf(xs[i + 1]) / x)])
    return x * total


for j in (1, 7, 20, 41, N - 1):
    print(f"({j}, {m.nstr(g(j), 20)}),")
