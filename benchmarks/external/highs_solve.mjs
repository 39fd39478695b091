#!/usr/bin/env node
// Solves one model file with HiGHS (the WebAssembly build published in the
// npm registry as `highs`) and prints one JSON line, for thrustsched-bench's
// external cross-check beside the `cbc` and `glpsol` programs.
//
//   node highs_solve.mjs MODEL.mps [--format mps|lp] [--time-limit S]
//                        [--highs-dir DIR]
//   node highs_solve.mjs --version [--highs-dir DIR]
//
// Output (stdout, one line):
//   {"solver":"highs","version":"1.15.3","status":"Optimal","has_solution":true,
//    "objective":0.0163,"bound":0.0163,"gap":0,"solve_s":1.2,"read_s":0.1}
// or, when the package cannot be loaded,
//   {"solver":"highs","status":"skipped","reason":"..."}   (exit code 3),
// or, when HiGHS fails on the model (e.g. out of WebAssembly memory),
//   {"solver":"highs","status":"error","reason":"..."}     (exit code 0).
// status is HiGHS' model status name (highs.constants.modelStatus), e.g.
// "optimal", "timeLimit", "infeasible"; objective/bound/gap are null when
// HiGHS has none (bound = info mip_dual_bound, gap = info mip_gap).
//
// The package is looked up in DIR/node_modules (DIR: --highs-dir, else the
// THRUSTSCHED_HIGHS_DIR environment variable, else .deps/highs in the
// repository, where scripts/setup.sh installs it), so nothing is needed on
// node's global path.
import { createRequire } from "node:module";
import { readFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));

function parseArgs(argv) {
  const a = { model: null, format: null, timeLimit: null, highsDir: null, version: false };
  for (let i = 0; i < argv.length; ++i) {
    const k = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) throw new Error(`${k} needs a value`);
      return argv[++i];
    };
    if (k === "--format") a.format = next();
    else if (k === "--time-limit") a.timeLimit = Number(next());
    else if (k === "--highs-dir") a.highsDir = next();
    else if (k === "--version") a.version = true;
    else if (k.startsWith("--")) throw new Error(`unknown option ${k}`);
    else if (a.model === null) a.model = k;
    else throw new Error(`unexpected argument ${k}`);
  }
  if (a.version) return a;
  if (a.model === null) throw new Error("usage: highs_solve.mjs MODEL [--format mps|lp] [--time-limit S] [--highs-dir DIR]");
  if (a.format === null) a.format = a.model.toLowerCase().endsWith(".lp") ? "lp" : "mps";
  if (a.format !== "mps" && a.format !== "lp") throw new Error(`--format ${a.format}: mps or lp`);
  if (a.timeLimit !== null && !(a.timeLimit > 0)) throw new Error("--time-limit must be > 0");
  return a;
}

function print(obj) {
  process.stdout.write(JSON.stringify(obj) + "\n");
}

function finite(x) {
  const v = typeof x === "bigint" ? Number(x) : x;
  return typeof v === "number" && Number.isFinite(v) ? v : null;
}

function skip(reason) {
  print({ solver: "highs", status: "skipped", reason });
  process.exit(3);
}

let args;
try {
  args = parseArgs(process.argv.slice(2));
} catch (e) {
  process.stderr.write(`highs_solve: ${e.message}\n`);
  process.exit(2);
}

const highsDir = resolve(args.highsDir ?? process.env.THRUSTSCHED_HIGHS_DIR ?? join(here, "../../.deps/highs"));
let loadHighs, version;
try {
  const req = createRequire(join(highsDir, "package.json"));
  const main = req.resolve("highs");
  loadHighs = req(main);
  // The package's "exports" hide package.json: read it next to build/.
  version = JSON.parse(readFileSync(join(dirname(main), "..", "package.json"), "utf8")).version;
} catch (e) {
  skip(`npm package highs not found in ${highsDir} (scripts/setup.sh installs it)`);
}

if (args.version) {
  // One line for the report's header: the package and the HiGHS it wraps.
  const highs = await loadHighs();
  print({ solver: "highs", version, highs_version: highs.version.string });
  process.exit(0);
}

let data;
try {
  data = readFileSync(args.model);
} catch (e) {
  process.stderr.write(`highs_solve: cannot read ${args.model}: ${e.message}\n`);
  process.exit(2);
}

const highs = await loadHighs();
const codeToName = Object.fromEntries(
  Object.entries(highs.constants.modelStatus).map(([name, code]) => [code, name]));

const t0 = performance.now();
let model;
try {
  // The persistent API reads MPS (free or fixed) as well as CPLEX LP; the
  // legacy highs.solve() takes LP text only.
  model = highs.createModel({ format: args.format, data: new Uint8Array(data) });
} catch (e) {
  // A model too large for the WebAssembly memory (this build grows it to
  // 2 GiB at most) fails here or in run(): a result, not a crash.
  print({ solver: "highs", version, status: "error", reason: `cannot load the model: ${e.message ?? e}` });
  process.exit(0);
}
const readS = (performance.now() - t0) / 1000;
try {
  // No `threads` option: the package creates every instance with threads = 1
  // and parallel = off (its WebAssembly build is single-threaded) and refuses
  // to change them, which matches the `threads 1` the bench gives the cbc
  // program.
  const opts = { output_flag: false };
  if (args.timeLimit !== null) opts.time_limit = args.timeLimit;
  try {
    model.options.set(opts);
  } catch (e) {
    skip(`option rejected: ${e.message ?? e}`);
  }
  const t1 = performance.now();
  let runError = null;
  try {
    model.run();
  } catch (e) {
    runError = e;
  }
  const solveS = (performance.now() - t1) / 1000;
  if (runError !== null) {
    print({ solver: "highs", version, status: "error", reason: String(runError.message ?? runError),
            has_solution: false, objective: null, bound: null, gap: null, solve_s: solveS, read_s: readS });
    process.exit(0);
  }
  const status = codeToName[model.getModelStatus()] ?? `status ${model.getModelStatus()}`;
  // primal_solution_status 2 = feasible (HiGHS' kSolutionStatusFeasible).
  const hasSolution = Number(model.info.get("primal_solution_status")) === 2;
  const info = (k) => {
    try {
      return finite(model.info.get(k));
    } catch {
      return null;
    }
  };
  print({
    solver: "highs", version, status, has_solution: hasSolution,
    objective: hasSolution ? info("objective_function_value") : null,
    bound: info("mip_dual_bound"), gap: hasSolution ? info("mip_gap") : null,
    solve_s: solveS, read_s: readS,
  });
} finally {
  model.dispose();
}
