#!/usr/bin/env python3
"""A gsplat-style training loop that shows its Gaussians on the display every N steps.

The loop is a stub of a 3DGS trainer (gsplat, nerfstudio): parameters kept raw (means, log
scales, unnormalised quaternions, opacity logits, SH) as torch tensors with requires_grad, an
optimiser step each iteration. Its display step hands the current parameters to lfd.Window,
which renders and shows them on its own threads: the loop does not wait for the display.

    python3 training_loop.py --calibration visual.json [--steps 300] [--every 25] [--simulated]
    python3 training_loop.py --device auto

Without torch (python3-torch) the same loop runs on numpy arrays.
"""
import argparse
import time

import numpy as np

import lfd

try:
    import torch
except ImportError:  # numpy stands in: lfd takes either
    torch = None


def initial_parameters(count, rng):
    """Random Gaussians in a unit box, stored as a 3DGS trainer keeps them."""
    params = dict(
        means=rng.uniform(-1, 1, (count, 3)),
        log_scales=np.log(np.full((count, 3), 0.08)),
        rotations=np.tile([1.0, 0, 0, 0], (count, 1)),
        opacity_logits=np.zeros(count),
        sh=np.concatenate([rng.uniform(-1, 1, (count, 1, 3)), np.zeros((count, 3, 3))], axis=1),
    )
    params = {k: v.astype(np.float32) for k, v in params.items()}
    if torch is not None:
        params = {k: torch.tensor(v, requires_grad=True) for k, v in params.items()}
    return params


def training_step(params, target, learning_rate=0.05):
    """One step pulling the means toward a target shape (a sphere): what an optimiser step does to
    the parameters, without a rasterizer's loss."""
    if torch is not None:
        loss = ((params["means"] - target) ** 2).sum()
        loss.backward()
        with torch.no_grad():
            for p in params.values():
                if p.grad is not None:
                    p -= learning_rate * p.grad
                    p.grad.zero_()
        return float(loss)
    grad = 2 * (params["means"] - target)
    params["means"] -= learning_rate * grad
    return float(((params["means"] - target) ** 2).sum())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--calibration", help="visual.json or calibration.json")
    source.add_argument("--device", default="auto", help="an attached Looking Glass: auto or a serial")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--every", type=int, default=25, help="show the Gaussians every N steps")
    parser.add_argument("--count", type=int, default=2000, help="Gaussians")
    parser.add_argument("--simulated", action="store_true", help="the simulated display window")
    parser.add_argument("--views", type=int, help="views (default: the display's recommendation)")
    args = parser.parse_args()

    display = lfd.Display.load(args.calibration) if args.calibration else lfd.Display.from_device(args.device)
    rng = np.random.default_rng(0)
    params = initial_parameters(args.count, rng)
    directions = rng.normal(size=(args.count, 3))
    target = (0.6 * directions / np.linalg.norm(directions, axis=1, keepdims=True)).astype(np.float32)
    if torch is not None:
        target = torch.from_numpy(target)

    with lfd.Window(display, simulated=args.simulated) as window:
        for step in range(1, args.steps + 1):
            loss = training_step(params, target)
            if step % args.every == 0 or step == args.steps:
                # Raw parameters as stored; lfd activates them (exp, sigmoid, normalise).
                window.update(lfd.Gaussians(**params), views=args.views)
                print(f"step {step}: loss {loss:.4f}, shown")
        window.wait()
        time.sleep(1.0)  # the last state on screen a moment before the window closes


if __name__ == "__main__":
    main()
