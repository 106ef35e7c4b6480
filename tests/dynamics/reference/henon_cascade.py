#!/usr/bin/env python3
"""Period-doubling values of the area-preserving Henon map x' = 1 - a x^2 + y, y' = -x, computed in 40-digit
arithmetic from an independent formulation: the orbit as a cyclic second-order recurrence
x_{n+1} + x_{n-1} = 1 - a x_n^2 (n mod N) and the doubling condition tr M = -2 on the monodromy matrix
M = prod [[-2 a x_n, 1], [-1, 0]], solved jointly for (x_0..x_{N-1}, a) by Newton's method (mpmath.findroot).
Starting guesses: one orbit point and a parameter value near the doubling (any that converge)."""
import sys
import mpmath as mp

mp.mp.dps = 40


def orbit_from(x0, y0, a, n):
    xs = []
    x, y = mp.mpf(x0), mp.mpf(y0)
    for _ in range(n):
        xs.append(x)
        x, y = 1 - a * x * x + y, -x
    return xs


def doubling(n, x0, y0, a0):
    def equations(*v):
        xs, a = v[:n], v[n]
        eqs = [xs[(i + 1) % n] + xs[(i - 1) % n] - 1 + a * xs[i] ** 2 for i in range(n)]
        m = mp.eye(2)
        for x in xs:
            m = mp.matrix([[-2 * a * x, 1], [-1, 0]]) * m
        eqs.append(m[0, 0] + m[1, 1] + 2)
        return eqs

    start = orbit_from(x0, y0, mp.mpf(a0), n) + [mp.mpf(a0)]
    sol = mp.findroot(equations, start, tol=mp.mpf(10) ** -35, maxsteps=200)
    return sol[n]


if __name__ == "__main__":
    # rows "order,a,x,y" of rollviz bifurcation-tree's CSV: a point near each doubling
    for line in sys.stdin:
        n, a, x, y = line.split(",")
        print(n, mp.nstr(doubling(int(n), x, y, a), 20))
