#!/usr/bin/env python3
"""The README's CI recipe, run: its YAML parsed and every step carried out as a CI would.

Each job of the recipe (a matrix job once per matrix value) runs in a fresh "checkout" of its
own: a folder holding a small suite in scenes/ (with scenes/expectations.txt) and build/bin/
crosscheck. `run:` steps run with bash in that folder after ${{ matrix.KEY }} is substituted;
`actions/checkout` is the fresh folder; `actions/upload-artifact` and `download-artifact` copy
folders through an artifact store as GitHub's v4 actions do (a download without a name puts each
artifact in PATH/NAME); the set-up step must be the main job's own (`bash scripts/setup.sh main`,
as scripts/main.sh runs it) and is not run, as the tests' build already holds crosscheck.
Checked: the recipe is valid YAML with a shard job over a matrix and a merge job after it; every
command exits as the recipe expects (a shard 0 or 1: continue-on-error must not hide a usage
error); the merge exits 0 (every result known), and its results.json equals, timings aside, an
unsharded run's over the same suite. A step this test does not know fails it, so the recipe
cannot drift from what was tested.

Usage: ci_recipe_test.py CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys

import yaml

crosscheck, source, artifacts = sys.argv[1:4]
work = os.path.join(artifacts, "ci_recipe")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# The suite: five quick scenes that pass and one deliberately broken file known to crash.
SUITE = ["scenes/top_left_rule.json", "scenes/culling.json", "scenes/blend_factors.json",
         "scenes/depth_compare.json", "tests/data/conformance/flat_triangle.json",
         "tests/data/conformance/malformed.json"]
EXPECTATIONS = "# the CI recipe test's suite\nmalformed, Crash   # deliberately broken JSON\n"


def fail(message):
    print("ci_recipe_test: " + message, file=sys.stderr)
    sys.exit(1)


def recipe_text():
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    start = readme.find("A CI recipe")
    if start < 0:
        fail("README.md has no 'A CI recipe' section")
    block = re.search(r"```yaml\n(.*?)```", readme[start:], re.S)
    if not block:
        fail("README.md's CI recipe has no ```yaml block")
    return block.group(1)


def checkout(name):
    root = os.path.join(work, name)
    os.makedirs(os.path.join(root, "scenes"))
    os.makedirs(os.path.join(root, "build", "bin"))
    for scene in SUITE:
        shutil.copy(os.path.join(source, scene), os.path.join(root, "scenes"))
    with open(os.path.join(root, "scenes", "expectations.txt"), "w") as f:
        f.write(EXPECTATIONS)
    os.symlink(os.path.abspath(crosscheck), os.path.join(root, "build", "bin", "crosscheck"))
    return root


def main_job_setup():
    main = open(os.path.join(source, "scripts", "main.sh"), encoding="utf-8").read()
    found = re.search(r"^(bash scripts/setup\.sh \w+)$", main, re.M)
    if not found:
        fail("scripts/main.sh does not run scripts/setup.sh")
    return found.group(1)


store = {}  # artifact name -> folder


def substituted(value, matrix, instance):
    """The step with ${{ matrix.KEY }} replaced in every string; any other expression fails."""
    if isinstance(value, dict):
        return {k: substituted(v, matrix, instance) for k, v in value.items()}
    if isinstance(value, list):
        return [substituted(v, matrix, instance) for v in value]
    if not isinstance(value, str):
        return value
    for key, replacement in matrix.items():
        value = value.replace("${{ matrix.%s }}" % key, str(replacement))
    if "${{" in value:
        fail("job %s: an expression this test does not substitute: %s" % (instance, value))
    return value


def run_job(job_name, job, matrix):
    instance = job_name + "".join("-%s%s" % kv for kv in matrix.items())
    root = checkout(instance)
    steps = job.get("steps") or fail("job %s has no steps" % job_name)
    if steps[0].get("uses", "").split("@")[0] != "actions/checkout":
        fail("job %s does not start with actions/checkout" % job_name)
    statuses = []
    for step in steps[1:]:
        step = substituted(step, matrix, instance)
        uses = step.get("uses", "").split("@")[0]
        if "run" in step:
            command = re.sub(r"\s*\n\s*", " ", step["run"].strip())
            if command.startswith("bash scripts/setup.sh"):
                if command != main_job_setup():
                    fail("job %s sets up with '%s', not the main job's '%s'" % (instance, command, main_job_setup()))
                continue
            log = os.path.join(work, instance + ".log")
            with open(log, "a") as out:
                out.write("$ %s\n" % command)
                out.flush()
                status = subprocess.call(["bash", "-c", command], cwd=root, stdout=out, stderr=subprocess.STDOUT)
            allowed = (0, 1) if step.get("continue-on-error") else (0,)
            if status not in allowed:
                fail("job %s: '%s' exited %d (see %s)" % (instance, command, status, log))
            statuses.append(status)
        elif uses == "actions/upload-artifact":
            name, path = step["with"]["name"], step["with"]["path"]
            if not os.path.isdir(os.path.join(root, path)):
                fail("job %s uploads %s, which the job did not write" % (instance, path))
            if name in store:
                fail("job %s uploads artifact %s twice" % (instance, name))
            store[name] = os.path.join(root, path)
        elif uses == "actions/download-artifact":
            into = os.path.join(root, step["with"]["path"])
            for name, folder in store.items():
                shutil.copytree(folder, os.path.join(into, name))
        else:
            fail("job %s: a step this test does not simulate: %s" % (instance, step))
    return root, statuses


try:
    recipe = yaml.safe_load(recipe_text())
except yaml.YAMLError as error:
    fail("README.md's CI recipe is not valid YAML: " + " ".join(str(error).split()))
jobs = recipe.get("jobs") or fail("the recipe has no jobs")
if set(jobs) != {"shard", "merge"} or jobs["merge"].get("needs") != "shard":
    fail("expected jobs 'shard' and 'merge' (needs: shard), found %s" % list(jobs))
shards = jobs["shard"]["strategy"]["matrix"]["shard"]
if len(shards) < 2:
    fail("the shard matrix has fewer than 2 shards: %s" % shards)
for value in shards:
    run_job("shard", jobs["shard"], {"shard": value})
root, statuses = run_job("merge", jobs["merge"], {})
if statuses != [0]:
    fail("the merge job ran %s, expected one command exiting 0" % statuses)

# The merged run against one unsharded run of the same suite, from the same checkout.
merged = os.path.join(root, "out", "report")
for name in ("index.html", "junit.xml", "results.json"):
    if not os.path.isfile(os.path.join(merged, name)):
        fail("the merge wrote no %s" % name)
status = subprocess.call(["build/bin/crosscheck", "report", "--jobs", "2", "--expectations", "scenes/expectations.txt",
                          "-o", "out/unsharded"], cwd=root, stdout=subprocess.DEVNULL)
if status != 0:
    fail("the unsharded run exited %d" % status)


def without_timings(value):
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    if isinstance(value, dict):
        return {k: 0 if k in ("seconds", "finished") or k.endswith("milliseconds") else without_timings(v)
                for k, v in value.items()}
    return value


def results(folder):
    with open(os.path.join(folder, "results.json"), encoding="utf-8") as f:
        value = without_timings(json.load(f))
    value["jobs"] = 0  # the merge records the most of any shard
    value["junit_file"] = ""  # the merge writes its JUnit beside results.json; the unsharded run none
    return value


a, b = results(merged), results(os.path.join(root, "out", "unsharded"))
if a != b:
    for key in a:
        if a[key] != b.get(key):
            fail("the merged results.json differs from the unsharded run's in '%s'" % key)
    fail("the merged results.json differs from the unsharded run's")
outcomes = {s["name"]: s["outcome"] for s in a["scenes"]}
if len(outcomes) != len(SUITE) or outcomes.get("malformed") != "ExpectedFail":
    fail("unexpected scenes or outcomes in the merged run: %s" % outcomes)
print("ci_recipe_test: %d shards and their merge as the README's recipe runs them: %d scenes, %s"
      % (len(shards), len(outcomes), ", ".join(sorted(set(outcomes.values())))))
