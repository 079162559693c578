#!/usr/bin/env python3
"""Writes Carom's collision sounds, synthesised here, to resources/sounds/.

Standard library only and a fixed seed, so running it again gives the same bytes.
Usage: scripts/make-sounds.py [OUTPUT_DIR]
"""

import math
import os
import random
import struct
import sys
import wave

RATE = 44100
# Carom plays each sound as an endless loop and stops it itself, after at least 300 ms
# (ui/sound/sound_board.cpp), in this silence: Qt 6.4's QSoundEffect, reused or left to end a
# sound on its own, goes silent for good after a few plays and can crash on a late drain. The
# silence leaves room for the server's ~100 ms of buffer and for a stop that comes late because
# the GUI thread stalled, before the loop comes round again.
TAIL_SILENCE = 1.0
# It also often loses the first 5-20 ms of a fresh stream, which is most of a clack; starting
# with 40 ms of silence keeps the attack, at the price of 40 ms more latency.
LEAD_SILENCE = 0.04


def render(duration, partials, noise_amp, noise_tau, noise_smooth, seed, peak):
    """Sum of exponentially decaying sines plus a decaying noise burst, normalised to peak.

    partials: (frequency Hz, amplitude, decay time constant s, phase) tuples.
    noise_smooth: one-pole low-pass coefficient for the noise (0 = white, near 1 = dull).
    """
    rng = random.Random(seed)
    n = int(duration * RATE)
    out = []
    lp = 0.0
    for i in range(n):
        t = i / RATE
        s = 0.0
        for freq, amp, tau, phase in partials:
            s += amp * math.exp(-t / tau) * math.sin(2.0 * math.pi * freq * t + phase)
        lp = noise_smooth * lp + (1.0 - noise_smooth) * rng.uniform(-1.0, 1.0)
        s += noise_amp * math.exp(-t / noise_tau) * lp
        out.append(s)
    # A 0.2 ms attack avoids a DC step click; a 5 ms tail fade ends exactly at zero.
    attack = int(0.0002 * RATE)
    tail = int(0.005 * RATE)
    for i in range(attack):
        out[i] *= i / attack
    for i in range(tail):
        out[n - 1 - i] *= i / tail
    top = max(abs(v) for v in out) or 1.0
    return ([0.0] * int(LEAD_SILENCE * RATE) + [v * peak / top for v in out] +
            [0.0] * int(TAIL_SILENCE * RATE))


def write_wav(path, samples):
    with wave.open(path, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(RATE)
        w.writeframes(b"".join(
            struct.pack("<h", max(-32767, min(32767, round(v * 32767)))) for v in samples))


def ball_ball():
    # Hard phenolic balls: a very short broadband tick, then a few inharmonic high partials
    # that die within tens of milliseconds.
    rng = random.Random(1)
    partials = [
        (2350.0, 1.00, 0.012, rng.uniform(0, math.pi)),
        (3710.0, 0.70, 0.009, rng.uniform(0, math.pi)),
        (5180.0, 0.45, 0.007, rng.uniform(0, math.pi)),
        (6930.0, 0.30, 0.005, rng.uniform(0, math.pi)),
        (1210.0, 0.25, 0.018, rng.uniform(0, math.pi)),
    ]
    return render(0.080, partials, noise_amp=1.6, noise_tau=0.0015, noise_smooth=0.1,
                  seed=11, peak=0.85)


def ball_wall():
    # A ball into a cushion or wall: low, damped body modes and a muffled noise burst,
    # slower to fade and with little above a kilohertz.
    rng = random.Random(2)
    partials = [
        (105.0, 1.00, 0.045, rng.uniform(0, math.pi)),
        (173.0, 0.80, 0.035, rng.uniform(0, math.pi)),
        (262.0, 0.50, 0.025, rng.uniform(0, math.pi)),
        (415.0, 0.30, 0.015, rng.uniform(0, math.pi)),
        (690.0, 0.15, 0.008, rng.uniform(0, math.pi)),
    ]
    return render(0.120, partials, noise_amp=2.5, noise_tau=0.006, noise_smooth=0.93,
                  seed=12, peak=0.9)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "resources", "sounds")
    os.makedirs(out_dir, exist_ok=True)
    for name, samples in (("ball-ball.wav", ball_ball()), ("ball-wall.wav", ball_wall())):
        path = os.path.join(out_dir, name)
        write_wav(path, samples)
        print(f"{os.path.normpath(path)}: {len(samples)} samples")


if __name__ == "__main__":
    main()
