#!/usr/bin/env python3
"""A ternary mixture's theory and DSMC, side by side, with the residuals below (v1 Fig. 6's mixture).

Reads the scene compare/scenes/bo1-fig06.toml (m = 1, 100, 500; sigma = m^(1/3); n = 0.1 each; eps = 0.5), optionally
with fewer particles and replicas at quick fidelity (the scene as a dict, read back by granmix.Scene.from_dict), runs
the theory of its judged level and the DSMC, and draws each species' MSD (theory: lines; DSMC: points with their
standard errors) over the relative residual (dsmc - theory)/theory with its error bar.

    PYTHONPATH=build/python python3 examples/python/ternary.py ternary.png [--particles 3000 --replicas 4] [--level kinetic]

The judged level (kinetic-converged-grid) takes tens of seconds; --level kinetic draws the first-Sonine kinetic theory
in a fraction of a second.
"""
import argparse
import pathlib
import tomllib

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)
import numpy as np  # noqa: E402

import granmix  # noqa: E402

SCENE = pathlib.Path(__file__).resolve().parents[2] / 'compare' / 'scenes' / 'bo1-fig06.toml'


def load(path, particles, replicas, end):
    """The scene, with the quick fidelity's particles and replicas and the last time replaced where given."""
    with open(path, 'rb') as f:
        d = tomllib.load(f)
    quick = d['dsmc']['quick']
    if particles:
        quick['particles'] = particles
    if replicas:
        quick['replicas'] = replicas
    if end:
        d['time']['end'] = end
    return granmix.Scene.from_dict(d)


def paired(theory, dsmc, species, column):
    """Theory and DSMC values of one species at the DSMC's times."""
    th, ds = theory.where(species=species), dsmc.where(species=species)
    at = {t: v for t, v in zip(th['t'], th[column])}
    return ds['t'], np.array([at[t] for t in ds['t']]), ds[column], ds[column + '_err']


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('png', help='the figure to write (PNG)')
    parser.add_argument('--scene', default=str(SCENE), help='a scene file with msd (default: bo1-fig06)')
    parser.add_argument('--particles', type=int, help="quick fidelity's particles (default: the scene's)")
    parser.add_argument('--replicas', type=int, help="quick fidelity's replicas (default: the scene's)")
    parser.add_argument('--end', type=float, help="the last time (default: the scene's)")
    parser.add_argument('--level', help="one theory level's curves instead of the scene's judged level (granmix.levels())")
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--threads', type=int, default=0, help='DSMC threads (0: all cores)')
    args = parser.parse_args()

    scene = load(args.scene, args.particles, args.replicas, args.end)
    theory = granmix.theory(scene, level=args.level)
    dsmc = granmix.dsmc(scene, fidelity='quick', seed=args.seed, threads=args.threads)
    print(f'{scene.name}: theory ({theory.level}) {theory.info["seconds"]:.2f} s; DSMC {dsmc.info["particles"]} particles x '
          f'{dsmc.info["replicas"]} replicas, {dsmc.info["collisions"]:.3g} collisions, {dsmc.info["seconds"]:.2f} s')

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 6.4), gridspec_kw={'height_ratios': [3, 1.4]})
    for k in range(1, scene.species + 1):
        th = theory.where(species=k)
        line, = top.loglog(th['t'], th['msd'], label=f'species {k}, theory')
        t, expected, mean, err = paired(theory, dsmc, k, 'msd')
        top.errorbar(t, mean, yerr=err, fmt='o', ms=3, color=line.get_color(), label=f'species {k}, DSMC')
        bottom.errorbar(t, mean / expected - 1, yerr=err / np.abs(expected), fmt='o', ms=3, color=line.get_color())
    top.set_ylabel('MSD ⟨R_k²(t)⟩')
    top.set_title(scene.title, fontsize=9)
    top.legend(fontsize=7, ncol=2)
    bottom.axhline(0.0, color='black', lw=0.8)
    bottom.set_xscale('log')
    bottom.set_xlabel('t')
    bottom.set_ylabel('(DSMC − theory)/theory')
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f'figure -> {args.png}')


if __name__ == '__main__':
    main()
