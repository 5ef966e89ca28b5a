// The command line's input: a file's text, or standard input's for '-'.
import { readFile } from 'node:fs/promises';

export async function readInput(path) {
  if (path !== '-') return readFile(path, 'utf8');
  const chunks = [];
  for await (const chunk of process.stdin) chunks.push(chunk);
  return Buffer.concat(chunks).toString('utf8');
}
