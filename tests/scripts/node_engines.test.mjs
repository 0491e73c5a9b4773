// The Node.js version check of scripts/setup: npm's range forms read as npm reads them.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { satisfies } from '../../scripts/check-node-engines.mjs';

test('lower bounds', () => {
  assert.equal(satisfies('18.20.4', '>=18'), true);
  assert.equal(satisfies('18.20.4', '>=20'), false);
  assert.equal(satisfies('20.0.0', '>=20'), true);
  assert.equal(satisfies('18.20.4', '>=10.0.0'), true);
  assert.equal(satisfies('18.20.4', '>18.20'), false);
  assert.equal(satisfies('18.21.0', '>18.20'), true);
});

test('upper bounds, ranges and alternatives', () => {
  assert.equal(satisfies('18.20.4', '<18.20'), false);
  assert.equal(satisfies('18.19.9', '<18.20'), true);
  assert.equal(satisfies('18.20.9', '<=18.20'), true);
  assert.equal(satisfies('18.21.0', '<=18.20'), false);
  assert.equal(satisfies('18.20.4', '>=16 <19'), true);
  assert.equal(satisfies('19.0.0', '>=16 <19'), false);
  assert.equal(satisfies('18.20.4', '^14.17.0 || >=16.0.0'), true);
  assert.equal(satisfies('15.0.0', '^14.17.0 || >=16.0.0'), false);
  assert.equal(satisfies('18.20.4', '16 - 18'), true);
  assert.equal(satisfies('19.0.0', '16 - 18'), false);
});

test('caret, tilde, x-ranges and any', () => {
  assert.equal(satisfies('18.20.4', '^18.2.0'), true);
  assert.equal(satisfies('19.0.0', '^18.2.0'), false);
  assert.equal(satisfies('0.2.5', '^0.2.3'), true);
  assert.equal(satisfies('0.3.0', '^0.2.3'), false);
  assert.equal(satisfies('0.0.4', '^0.0.3'), false);
  assert.equal(satisfies('18.20.4', '~18.20.1'), true);
  assert.equal(satisfies('18.21.0', '~18.20.1'), false);
  assert.equal(satisfies('18.20.4', '18.x'), true);
  assert.equal(satisfies('20.1.0', '18.x'), false);
  assert.equal(satisfies('18.20.4', '*'), true);
  assert.equal(satisfies('18.20.4', ''), true);
});

test('a range it cannot read is an error naming where', () => {
  assert.throws(() => satisfies('18.20.4', '>=eighteen', 'pkg'), /pkg: cannot read version/);
});
