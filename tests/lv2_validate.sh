#!/bin/sh
# Validates the fulgur.lv2 bundle's Turtle against the installed LV2 spec.
# usage: lv2_validate.sh BUNDLE_DIR. Exit 77 (skipped) if the validator is
# missing (Debian: lv2-dev and sordi).
bundle=$1
if ! command -v lv2_validate >/dev/null 2>&1 || ! command -v sord_validate >/dev/null 2>&1; then
    echo "SKIPPED: lv2_validate or sord_validate not installed (Debian 12: lv2-dev, sordi)"
    exit 77
fi
out=$(lv2_validate "$bundle"/*.ttl 2>&1)
rc=$?
echo "$out"
# sord_validate reports "Found N errors"; anything but 0 fails
[ $rc -eq 0 ] && echo "$out" | grep -q "Found 0 errors"
