// Builds the dashboard into crates/hub/assets/dashboard/, the directory the hub embeds
// (include_bytes!). Output file names are fixed and the build is deterministic, so
// `git diff --exit-code` after a rebuild tells whether the committed bundle is stale.
//
//   node build.mjs              the bundle (minified, no source maps)
//   node build.mjs --out DIR    the bundle into DIR instead (the staleness check)
//   node build.mjs --tests      also the unit tests into test-build/ (for `node --test`)
import * as esbuild from "esbuild";
import { copyFileSync, mkdirSync, readdirSync, rmSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const outArg = process.argv.indexOf("--out");
const out = outArg > 0 ? process.argv[outArg + 1] : join(here, "..", "crates", "hub", "assets", "dashboard");
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const common = { bundle: true, logLevel: "warning", legalComments: "none", charset: "utf8", target: ["es2022", "chrome110", "firefox115", "safari16"] };
await esbuild.build({ ...common, entryPoints: [join(here, "src/main.ts")], outfile: join(out, "app.js"), format: "esm", minify: true });
await esbuild.build({ ...common, entryPoints: [join(here, "src/style.css")], outfile: join(out, "app.css"), minify: true });
copyFileSync(join(here, "index.html"), join(out, "index.html"));
console.log(`dashboard built into ${out}: ${readdirSync(out).join(", ")}`);

if (process.argv.includes("--tests")) {
  const testOut = join(here, "test-build");
  rmSync(testOut, { recursive: true, force: true });
  const tests = readdirSync(join(here, "test")).filter((f) => f.endsWith(".test.ts"));
  await esbuild.build({
    ...common,
    entryPoints: tests.map((f) => join(here, "test", f)),
    outdir: testOut,
    outExtension: { ".js": ".mjs" },
    platform: "node",
    format: "esm",
    target: "node20",
  });
}
