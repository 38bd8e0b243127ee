#!/usr/bin/env python3
"""Checks that every CTest test of a build is in exactly one tier (cmake/StylizeTestTiers.cmake):
one label of TIERS, besides `slow` and labels of its own (such as `benchmark`).

Usage: check_tiers.py [--list] BUILD_DIR [CTEST]. Reads `ctest --show-only=json-v1` in BUILD_DIR,
exits 1 naming each test without a tier or with two; --list prints each tier's tests and count.
"""
import json
import subprocess
import sys

TIERS = ("unit", "render", "realdata", "paraview", "cli", "corpus", "fuzz", "install")


def main():
    args = sys.argv[1:]
    listing = args[:1] == ["--list"]
    if listing:
        args = args[1:]
    if not 1 <= len(args) <= 2:
        sys.exit(__doc__)
    ctest = args[1] if len(args) > 1 else "ctest"
    shown = subprocess.run([ctest, "--show-only=json-v1"], cwd=args[0], capture_output=True,
                           text=True, check=True)
    tests = json.loads(shown.stdout)["tests"]
    by_tier = {tier: [] for tier in TIERS}
    slow = []
    bad = []
    for test in tests:
        labels = []
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                labels = prop["value"]
        tiers = [label for label in labels if label in TIERS]
        if len(tiers) != 1:
            bad.append("%s: %s" % (test["name"], "tiers %s" % ", ".join(tiers) if tiers
                                   else "no tier"))
            continue
        by_tier[tiers[0]].append(test["name"])
        if "slow" in labels:
            slow.append(test["name"])
    if listing:
        for tier in TIERS:
            print("%-9s %4d  %s" % (tier, len(by_tier[tier]), " ".join(by_tier[tier])))
        print("%-9s %4d  %s" % ("slow", len(slow), " ".join(slow)))
    for line in bad:
        print("FAIL: " + line)
    print("%d tests: %s; %d slow" % (len(tests), ", ".join(
        "%s %d" % (tier, len(by_tier[tier])) for tier in TIERS), len(slow)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
