#!/bin/sh
# Regenerate the GL 3.3 core loader from Debian's python3-glad, offline (--reproducible).
cd "$(dirname "$0")" && rm -rf include src && glad --reproducible --api gl:core=3.3 --out-path . c
