"""A process under test: prints its arguments, then exits with a code or waits.

    proc.py [--stderr] [--exit CODE] [--delay S] LINE...

Without --exit it runs until SIGINT/SIGTERM and then exits 0.
"""
import argparse
import signal
import sys
import time

parser = argparse.ArgumentParser()
parser.add_argument('--stderr', action='store_true')
parser.add_argument('--exit', type=int)
parser.add_argument('--delay', type=float, default=0.0)
parser.add_argument('lines', nargs='*')
args = parser.parse_args()
for signum in (signal.SIGINT, signal.SIGTERM):
    signal.signal(signum, lambda *_: sys.exit(0))
time.sleep(args.delay)
stream = sys.stderr if args.stderr else sys.stdout
for line in args.lines:
    print(line, file=stream, flush=True)
if args.exit is not None:
    sys.exit(args.exit)
while True:
    signal.pause()
