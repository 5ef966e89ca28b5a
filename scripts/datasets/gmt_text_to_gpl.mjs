#!/usr/bin/env node
// Converts GMT multisegment text (segments separated by lines starting with '>', one
// "x y" pair per line) from stdin into a .gpl file: each segment becomes one polyline.
// Usage: gmt ... | node scripts/datasets/gmt_text_to_gpl.mjs out.gpl
import { readFileSync } from 'node:fs';
import { writePolylines } from './dataset_file.mjs';

const out = process.argv[2];
if (!out) {
  console.error('usage: gmt_text_to_gpl.mjs <output.gpl>  (GMT multisegment text on stdin)');
  process.exit(2);
}

const polylines = [];
let current = null;
for (const line of readFileSync(0, 'utf8').split('\n')) {
  if (line.startsWith('>')) {
    current = null;
    continue;
  }
  const fields = line.trim().split(/\s+/);
  if (fields.length < 2 || fields[0] === '' || fields[0].startsWith('#')) continue;
  const x = Number(fields[0]);
  const y = Number(fields[1]);
  if (!Number.isFinite(x) || !Number.isFinite(y)) {
    console.error(`skipping a line that is not "x y": ${line}`);
    continue;
  }
  if (!current) polylines.push((current = []));
  current.push([x, y]);
}

const { points } = writePolylines(out, polylines);
console.log(`${out}: ${polylines.length} polylines, ${points} points`);
