#!/usr/bin/env python3
"""Settled temperature and diffusion ratios of a binary over its mass ratio and restitution coefficient.

For m2/m1 on a log grid and eps on a linear grid (equal diameters and densities), granmix.hcs gives the settled (HCS)
state as `granmix hcs --json` does: T2/T1 at the first Sonine order (T_ratio_sonine) and D2/D1 of v1 Eq. 19 (D_ratio).
Prints both tables and the time the scan took.

    PYTHONPATH=build/python python3 examples/python/hcs_scan.py [--masses 20] [--eps 15]
"""
import argparse
import time

import numpy as np

import granmix


def scan(mass_ratios, eps_values):
    """T2/T1 and D2/D1 on the grid (rows: mass ratio, columns: eps)."""
    T = np.empty((len(mass_ratios), len(eps_values)))
    D = np.empty_like(T)
    for i, mu in enumerate(mass_ratios):
        for j, eps in enumerate(eps_values):
            h = granmix.hcs(mass=[1.0, mu], diameter=[1.0, 1.0], density=[0.1, 0.1], eps=eps)
            T[i, j] = h['species'][1]['T_ratio_sonine']
            D[i, j] = h['species'][1]['D_ratio']
    return T, D


def print_table(name, values, mass_ratios, eps_values):
    print(f'\n{name} (rows m2/m1, columns eps)')
    print('m2/m1  ' + ' '.join(f'{e:8.2f}' for e in eps_values))
    for mu, row in zip(mass_ratios, values):
        print(f'{mu:6.3g} ' + ' '.join(f'{v:8.4g}' for v in row))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--masses', type=int, default=20, help='mass ratios m2/m1, log-spaced over [0.1, 100]')
    parser.add_argument('--eps', type=int, default=15, help='restitution coefficients, linear over [0.3, 0.99]')
    args = parser.parse_args()
    mass_ratios = np.geomspace(0.1, 100.0, args.masses)
    eps_values = np.linspace(0.3, 0.99, args.eps)
    start = time.perf_counter()
    T, D = scan(mass_ratios, eps_values)
    seconds = time.perf_counter() - start
    print_table('T2/T1, first Sonine', T, mass_ratios, eps_values)
    print_table('D2/D1, v1 Eq. 19', D, mass_ratios, eps_values)
    n = T.size
    print(f'\n{n} points in {seconds:.2f} s ({1e3 * seconds / n:.2f} ms per point)')


if __name__ == '__main__':
    main()
