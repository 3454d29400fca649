#!/usr/bin/env bash
# PrairieLearn external grader entrypoint: the student's files are in /grade/student,
# the results go to /grade/results/results.json (PrairieLearn docs/externalGrading.md).
# Put this file and a `lightlab` binary in serverFilesCourse/lightlab/. The image needs
# Mesa llvmpipe (libegl1 libegl-mesa0 libgl1-mesa-dri): build one FROM the grader image.
set -uo pipefail
mkdir -p /grade/results
# PrairieLearn's own job timeout (info.json, at most 600 s) must exceed lightlab's --timeout.
/grade/serverFilesCourse/lightlab/lightlab grade /grade/student --exercise basic-move-light \
    --format prairielearn -o /grade/results/results.json --timeout 120 --memory 2048
exit 0
