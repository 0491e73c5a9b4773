// Checks this machine's Node.js against the `engines.node` range of every package in
// package-lock.json, before `npm ci` installs them. Prints each package that does not fit, with
// its range and the Node.js found, and exits 1; exits 0 when all fit.
//
// Reads the range forms npm packages use (`>=18`, `^14.17.0 || >=16`, `~1.2`, `1.x`, `*`,
// `1.2 - 3`); a range it cannot read is an error naming the package, never a silent pass.
// No npm package is needed: it runs before node_modules exists.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';

function parseVersion(text, where) {
  const m = /^v?(\d+|[xX*])(?:\.(\d+|[xX*]))?(?:\.(\d+|[xX*]))?(?:[-+].*)?$/.exec(text);
  if (!m) throw new Error(`${where}: cannot read version "${text}"`);
  const part = (s) => (s === undefined || /^[xX*]$/.test(s) ? null : Number(s));
  return [part(m[1]), part(m[2]), part(m[3])];
}

function compare(a, b) {
  for (let i = 0; i < 3; ++i) {
    if (a[i] !== b[i]) return a[i] < b[i] ? -1 : 1;
  }
  return 0;
}

// The lowest version a partial version stands for, and the first one above it ("1.2" -> 1.2.0
// and 1.3.0).
function bounds(partial) {
  const low = partial.map((p) => p ?? 0);
  const wild = partial.indexOf(null);
  if (wild === 0) return { low, high: null };
  if (wild < 0) return { low, high: [low[0], low[1], low[2] + 1] };
  const high = low.slice();
  high[wild - 1] += 1;
  for (let i = wild; i < 3; ++i) high[i] = 0;
  return { low, high };
}

function satisfiesComparator(version, comparator, where) {
  if (comparator === '' || comparator === '*' || /^[xX]$/.test(comparator)) return true;
  const m = /^(>=|<=|>|<|=|\^|~)?\s*(.+)$/.exec(comparator);
  const op = m[1] ?? '=';
  const partial = parseVersion(m[2], where);
  const { low, high } = bounds(partial);
  const atLeast = (v) => compare(version, v) >= 0;
  const below = (v) => v === null || compare(version, v) < 0;
  switch (op) {
    case '>=': return atLeast(low);
    case '>': return high === null ? false : atLeast(high);
    case '<': return compare(version, low) < 0;
    case '<=': return below(high);
    case '=': return atLeast(low) && below(high);
    case '~': {
      const top = partial[1] === null ? [low[0] + 1, 0, 0] : [low[0], low[1] + 1, 0];
      return atLeast(low) && below(top);
    }
    case '^': {
      if (partial[0] === null) return true;
      let at = partial.findIndex((p) => p !== 0);
      if (at < 0) at = 2;
      if (partial[at] === null) at -= 1;
      const top = [0, 0, 0];
      for (let i = 0; i < at; ++i) top[i] = low[i];
      top[at] = low[at] + 1;
      return atLeast(low) && below(top);
    }
  }
  throw new Error(`${where}: cannot read comparator "${comparator}"`);
}

export function satisfies(versionText, range, where = 'range') {
  const version = parseVersion(versionText, where);
  return range.split('||').some((alternative) => {
    const text = alternative.trim();
    const hyphen = /^(\S+)\s+-\s+(\S+)$/.exec(text);
    if (hyphen) {
      return (
        satisfiesComparator(version, `>=${hyphen[1]}`, where) &&
        satisfiesComparator(version, `<=${hyphen[2]}`, where)
      );
    }
    const comparators = text.replace(/(>=|<=|>|<|=|\^|~)\s+/g, '$1').split(/\s+/);
    return comparators.every((c) => satisfiesComparator(version, c, where));
  });
}

function main() {
  const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
  const lockPath = path.join(root, 'package-lock.json');
  const lock = JSON.parse(readFileSync(lockPath, 'utf8'));
  const node = process.versions.node;
  const misfits = [];
  for (const [where, entry] of Object.entries(lock.packages ?? {})) {
    const range = entry.engines?.node;
    if (range === undefined) continue;
    const name = where.replace(/^.*node_modules\//, '') || '(the project)';
    if (!satisfies(node, range, `${lockPath}: ${name}`)) {
      misfits.push(`  ${name}@${entry.version} needs Node.js ${range}`);
    }
  }
  if (misfits.length > 0) {
    console.error(
      `scripts/setup: this machine's Node.js is ${node}, which these packages of ` +
        `package-lock.json do not support:\n${misfits.join('\n')}\n` +
        'Install a Node.js they support, or pin releases whose engines include this one.',
    );
    process.exit(1);
  }
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  try {
    main();
  } catch (error) {
    console.error(`scripts/setup: ${error.message}`);
    process.exit(1);
  }
}
