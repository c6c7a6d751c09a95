// The page's default parameters (web/src/params.ts, DEFAULT_PARAMS) are the core's. The page
// sends every field to the worker (toRemeshParams), so its copy, not the core's defaults
// (core/remesher.h, core/cluster/metric.h), decides every solve on the page; nothing else
// ties the two. A solve from the page's request and one with only `panels` set (the core's
// defaults) must give the same panels, limits and quality. Needs the wasm build.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { DEFAULT_PARAMS, toRemeshParams } from '../../build/web-tests/params.js';
import { json, loadModule, solve } from '../wasm/module.mjs';

const ff = await loadModule();

// The panels and the report (without its timings) of a solve of a 2000-triangle
// saddle at 100 panels (teleports move clusters only from about 64 up).
function solved(request) {
  const s = new ff.Session();
  try {
    assert.equal(json(s.loadShape('saddle', 2000)).ok, true);
    const status = json(s.setParams(JSON.stringify(request)));
    assert.equal(status.ok, true, status.message);
    solve(s);
    const report = json(s.reportJson());
    delete report.timings_s;
    return { obj: s.objText(), report };
  } finally {
    s.delete();
  }
}

test("the page's default parameters solve as the core's defaults do", () => {
  const panels = 100;
  const page = solved(toRemeshParams({ ...DEFAULT_PARAMS, panels }));
  const core = solved({ panels });
  assert.deepEqual(page.report, core.report);
  assert.equal(page.obj, core.obj);
});

// The comparison above sees each field the page sends: a page default one step away from the
// core's changes the report or the panels. Every field the page sends is in the list, so a
// field added to the page later fails here until it is added too.
test('a page default that differs from the core is caught', () => {
  const panels = 100;
  const core = solved({ panels });
  const changed = {
    seed: 2,
    lloydIterations: DEFAULT_PARAMS.lloydIterations - 1,
    panelRounds: DEFAULT_PARAMS.panelRounds - 1,
    retries: DEFAULT_PARAMS.retries - 1, // the report's retries_limit
    seeding: 'random',
    teleport: !DEFAULT_PARAMS.teleport,
    singlePointNodes: !DEFAULT_PARAMS.singlePointNodes,
    optimizePlanes: !DEFAULT_PARAMS.optimizePlanes,
    glass: !DEFAULT_PARAMS.glass,
    minCornerAngleDeg: DEFAULT_PARAMS.minCornerAngleDeg + 1,
    coplanarAngleDeg: DEFAULT_PARAMS.coplanarAngleDeg + 1,
  };
  const sent = Object.keys(toRemeshParams({ ...DEFAULT_PARAMS, panels }));
  assert.deepEqual(sent.filter((field) => field !== 'panels' && field !== 'weights').sort(), Object.keys(changed).sort());
  const variants = Object.entries(changed).map(([field, value]) => [field, { [field]: value }]);
  for (const weight of Object.keys(DEFAULT_PARAMS.weights))
    variants.push([`weights.${weight}`, { weights: { ...DEFAULT_PARAMS.weights, [weight]: DEFAULT_PARAMS.weights[weight] / 2 } }]);
  for (const [field, change] of variants) {
    const page = solved(toRemeshParams({ ...DEFAULT_PARAMS, panels, ...change }));
    assert.notDeepEqual({ obj: page.obj, report: page.report }, { obj: core.obj, report: core.report }, `${field} changed`);
  }
});
