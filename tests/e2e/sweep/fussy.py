#!/usr/bin/env python3
# A script metric that fails for runs of 3 s (unless FUSSY_FIXED is set):
# a sweep keeps the other trials, and measures only these again once fixed.
import json, os, sys
world = json.load(open(os.environ["OPENSWARM_WORLD"]))
if world["duration_s"] == 3 and not os.environ.get("FUSSY_FIXED"):
    sys.exit("fussy.py: 3 s is too long for me")
print("fussy", world["duration_s"])
