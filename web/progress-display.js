// Progress of the command line's long steps on stderr: on a terminal, one bar redrawn in
// place; elsewhere (a log file, a pipe), a plain line when a step starts and at every quarter.

const BAR = 30;
const LABEL = 26;  // 'triangulating: constraints': the bars of every step line up

export class ProgressDisplay {
  #stream;
  #tty;
  #drawn = '';    // what the bar shows now (tty)
  #label = null;  // the step of the last plain line, and its last quarter
  #quarter = -1;

  // stream: a writable with write(); tty: whether it is a terminal (stream.isTTY).
  constructor(stream, tty = stream.isTTY === true) {
    this.#stream = stream;
    this.#tty = tty;
  }

  // label: what is running ('triangulating: points'); fraction: 0 .. 1.
  update(label, fraction) {
    const percent = Math.floor(100 * Math.min(Math.max(fraction, 0), 1));
    if (this.#tty) {
      const filled = Math.round((BAR * percent) / 100);
      const text = `geocdt: ${label.padEnd(LABEL)} `
        + `[${'#'.repeat(filled)}${'-'.repeat(BAR - filled)}] ${percent}%`;
      if (text === this.#drawn) return;
      this.#drawn = text;
      this.#stream.write(`\r${text}\x1b[K`);
      return;
    }
    const quarter = Math.floor(percent / 25);
    if (label === this.#label && quarter <= this.#quarter) return;
    this.#label = label;
    this.#quarter = quarter;
    this.#stream.write(`geocdt: ${label} ${percent}%\n`);
  }

  // A message on a line of its own; the bar, if any, is cleared first.
  line(message) {
    this.clear();
    this.#stream.write(`geocdt: ${message}\n`);
  }

  clear() {
    if (this.#drawn === '') return;
    this.#stream.write('\r\x1b[K');
    this.#drawn = '';
  }
}
