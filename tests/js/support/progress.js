// What every sequence of onProgress events must satisfy.
import assert from 'node:assert/strict';

export const PHASES = ['sort', 'points', 'constraints', 'export'];

// events: [{ phase, fraction }] in the order received. Phases only move forward, fractions
// lie in [0, 1] and grow within a phase.
export function checkProgressEvents(events) {
  assert.ok(events.length > 0, 'at least one progress event');
  let last = { phase: -1, fraction: -1 };
  for (const [i, e] of events.entries()) {
    const phase = PHASES.indexOf(e.phase);
    assert.ok(phase >= 0, `event ${i}: unknown phase ${e.phase}`);
    assert.ok(e.fraction >= 0 && e.fraction <= 1, `event ${i}: fraction ${e.fraction}`);
    assert.ok(phase >= last.phase, `event ${i}: ${e.phase} after ${PHASES[last.phase]}`);
    if (phase === last.phase) {
      assert.ok(e.fraction > last.fraction,
        `event ${i}: ${e.phase} ${e.fraction} after ${last.fraction}`);
    }
    last = { phase, fraction: e.fraction };
  }
}
