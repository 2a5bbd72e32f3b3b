#!/usr/bin/env python3
"""Independent flux integral of an EULUMDAT file: the bilinear table integrated exactly in
gamma (linear I times sin), trapezoids in C over the unfolded full circle. Prints
integrated lumens (cd/klm x set-1 flux / 1000 x conversion factor) and the zonal sum."""
import math, sys

def lines_of(path):
    with open(path, 'rb') as f:
        return [l.decode('latin-1').strip() for l in f.read().replace(b'\r', b'').split(b'\n')]

def read(path):
    L = lines_of(path)
    num = lambda i: float(L[i - 1].replace(',', '.'))
    isym, mc, ng = int(num(3)), int(num(4)), int(num(6))
    sets = int(num(26))
    flux1 = num(29)
    conv = num(24)
    first = 27 + 6 * sets + 10
    C = [num(first + i) for i in range(mc)]
    G = [num(first + mc + i) for i in range(ng)]
    planes = {0: mc, 1: 1, 2: mc // 2 + 1, 3: mc // 2 + 1, 4: mc // 4 + 1}[isym]
    start = mc // 4 if isym == 3 else 0
    line = first + mc + ng
    stored = {}
    for k in range(planes):
        stored[C[start + k] if isym != 1 else 0.0] = [num(line + i) * flux1 / 1000 * conv for i in range(ng)]
        line += ng
    return isym, C, G, stored, num(23) / 100, flux1

def fold(isym, c):
    c %= 360
    if isym == 1: return 0.0
    if isym == 2: return c if c <= 180 else 360 - c
    if isym == 3: return 180 - c if c < 90 else (c if c <= 270 else 540 - c)
    if isym == 4:
        c = c if c <= 180 else 360 - c
        return c if c <= 90 else 180 - c
    return c

def plane_integral(I, G):
    s = 0.0
    for a, b, ia, ib in zip(G, G[1:], I, I[1:]):
        ga, gb = math.radians(a), math.radians(b)
        slope = (ib - ia) / (gb - ga)
        F = lambda g: -(ia + slope * (g - ga)) * math.cos(g) + slope * math.sin(g)
        s += F(gb) - F(ga)
    return s

def main(path):
    isym, C, G, stored, lor, flux1 = read(path)
    full = C if isym != 1 else [0.0]
    vals = [stored[min(stored, key=lambda s: abs(s - fold(isym, c)))] for c in full]
    for c in full:
        assert min(abs(s - fold(isym, c)) for s in stored) < 1e-6, (c, fold(isym, c))
    if isym == 1:
        total = 2 * math.pi * plane_integral(vals[0], G)
        zonal = sum(2 * math.pi * 0.5 * (vals[0][i] + vals[0][i + 1]) *
                    (math.cos(math.radians(G[i])) - math.cos(math.radians(G[i + 1]))) for i in range(len(G) - 1))
    else:
        total = zonal = 0.0
        n = len(full)
        for k in range(n):
            c0, c1 = full[k], (full[k + 1] if k + 1 < n else full[0] + 360)
            w = math.radians(c1 - c0)
            a, b = vals[k], vals[(k + 1) % n]
            total += w * 0.5 * (plane_integral(a, G) + plane_integral(b, G))
            for i in range(len(G) - 1):
                zonal += w * 0.25 * (a[i] + a[i + 1] + b[i] + b[i + 1]) * \
                    (math.cos(math.radians(G[i])) - math.cos(math.radians(G[i + 1])))
    print(f"{path}: set-1 flux {flux1:g} lm, LORL {lor:.4f}, integrated {total:.2f} lm, zonal {zonal:.2f} lm, "
          f"LOR {total / flux1:.4f}")

for p in sys.argv[1:]:
    main(p)
