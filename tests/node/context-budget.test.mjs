// Node tests of the page's WebGL context budget (web/src/surfaces/context-budget.js): which book gives its context
// up, and the lease's hand-back and take-back through WEBGL_lose_context, on a fake canvas and context
// that behave as Chrome's do (the lost and restored events come in later tasks; a lost context gives out no extension).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ContextBudget, chooseContextToRelease } from '../../web/src/surfaces/context-budget.js';

globalThis.requestAnimationFrame ??= (callback) => setTimeout(() => callback(performance.now()), 0);

// Node has no IntersectionObserver: this one keeps the lease's callback on the canvas it observes, so a
// test reports a book in or out of view as the browser would.
globalThis.IntersectionObserver = class {
  constructor(callback) { this.callback = callback; }
  observe(target) { target.intersection = this; }
  disconnect() {}
};
const setVisible = (lease, visible) => lease.canvas.intersection.callback([{ isIntersecting: visible }]);

const tasks = (n = 4) => new Promise((resolve) => {
  const step = (left) => (left === 0 ? resolve() : setTimeout(() => step(left - 1), 0));
  step(n);
});

class FakeCanvas extends EventTarget {
  constructor() {
    super();
    this.style = {};
    this.parentElement = { style: {} };
    this.calls = [];
    const canvas = this;
    this.gl = {
      lost: false,
      isContextLost() { return this.lost; },
      getExtension(name) { return this.lost || name !== 'WEBGL_lose_context' ? null : canvas.extension; },
    };
    this.extension = {
      loseContext() {
        if (canvas.gl.lost) return;
        canvas.calls.push('lose');
        canvas.gl.lost = true;
        setTimeout(() => {
          const event = new Event('webglcontextlost', { cancelable: true });
          canvas.dispatchEvent(event);
          canvas.restoreAllowed = event.defaultPrevented;
        });
      },
      restoreContext() {
        canvas.calls.push('restore');
        if (!canvas.gl.lost || !canvas.restoreAllowed) return;
        setTimeout(() => {
          canvas.gl.lost = false;
          canvas.dispatchEvent(new Event('webglcontextrestored'));
        });
      },
    };
    // What BookView does on a lost context: allow the restore.
    this.addEventListener('webglcontextlost', (event) => event.preventDefault());
  }

  getContext(type) { return type === 'webgl2' ? this.gl : null; }
  toBlob(callback) { callback(null); }
}

function fakeView({ animating = false, position = 0 } = {}) {
  return {
    animating, position, renderer: {}, drawn: 0, renderRequests: 0,
    drawNow() { this.drawn++; },
    requestRender() { this.renderRequests++; },
  };
}

function book(budget, view = fakeView()) {
  const canvas = new FakeCanvas();
  const lease = budget.lease(canvas);
  lease.admit();
  lease.attach(view);
  return { canvas, lease, view };
}

test('node: chooseContextToRelease takes a book out of view before one in view, at rest before busy, then the longest unused', () => {
  assert.equal(chooseContextToRelease([]), -1);
  const idle = (visible, lastUsed) => ({ visible, busy: false, lastUsed });
  assert.equal(chooseContextToRelease([idle(true, 1), idle(false, 9), idle(true, 0)]), 1);
  assert.equal(chooseContextToRelease([idle(false, 5), idle(false, 2), idle(false, 7)]), 1);
  assert.equal(chooseContextToRelease([{ visible: false, busy: true, lastUsed: 0 }, idle(false, 4)]), 1);
  assert.equal(chooseContextToRelease([{ visible: false, busy: true, lastUsed: 3 }, idle(true, 0)]), 0);
  assert.equal(chooseContextToRelease([idle(true, 4), { visible: true, busy: true, lastUsed: 1 }]), 0);
});

test('node: a budget of 2 parks the least recently used book when a third is admitted, and refuses a bad size', async () => {
  assert.throws(() => new ContextBudget({ maxLive: 0 }), /maxLive/);
  const budget = new ContextBudget({ maxLive: 2 });
  const a = book(budget);
  const b = book(budget);
  assert.equal(budget.liveCount, 2);
  const c = book(budget);
  assert.equal(budget.liveCount, 2);
  assert.deepEqual([a.lease.state, b.lease.state, c.lease.state], ['parked', 'live', 'live']);
  assert.equal(a.canvas.gl.lost, true);
  assert.equal(a.view.drawn, 1, 'the last frame was drawn for the snapshot');
  assert.equal(a.canvas.style.opacity, '0', 'the context-less canvas is hidden behind its snapshot');
  assert.throws(() => a.lease.admit(), /handed its context back/);
});

test('node: a parked book scrolled into view takes its context back from the book out of view longest', async () => {
  const budget = new ContextBudget({ maxLive: 2 });
  const a = book(budget);
  const b = book(budget);
  const c = book(budget);  // parks a
  setVisible(a.lease, false);  // a is out of view
  setVisible(c.lease, false);
  setVisible(b.lease, false);  // b left the view after c: c goes first
  await tasks();
  setVisible(a.lease, true);
  assert.equal(a.lease.state, 'restoring');
  assert.equal(c.lease.state, 'parked');
  assert.equal(budget.liveCount, 2);
  await tasks(6);
  assert.equal(a.lease.state, 'live');
  assert.equal(a.canvas.gl.lost, false);
  assert.deepEqual(a.canvas.calls, ['lose', 'restore']);
  assert.equal(a.canvas.style.opacity, '', 'the canvas shows again once it has drawn');
  assert.equal(c.canvas.gl.lost, true);
});

test('node: a parked book keeps its clock running (turns land without drawing); in view, a turn asks for a context', async () => {
  const budget = new ContextBudget({ maxLive: 1 });
  const turning = book(budget, fakeView({ animating: true }));
  book(budget);  // parks the turning book
  await tasks();
  assert.equal(turning.lease.state, 'parked');
  assert.ok(turning.view.renderRequests > 0, 'the parked book was asked to keep ticking');

  const other = new ContextBudget({ maxLive: 1 });
  const resting = book(other);
  const newer = book(other);  // parks the resting book
  // A demand with the picture unchanged (a page image arriving) does not take the context back...
  resting.lease.demand();
  assert.equal(resting.lease.state, 'parked');
  // ... a jump (or a turn) does, from the book at rest.
  resting.view.position = 3;
  resting.lease.demand();
  assert.equal(resting.lease.state, 'restoring');
  assert.equal(newer.lease.state, 'parked');
  // Out of view, a parked book never asks.
  setVisible(newer.lease, false);
  newer.view.position = 5;
  newer.lease.demand();
  assert.equal(newer.lease.state, 'parked');
});

test('node: dispose frees the context at once and leaves the budget; a parked book lost and restored by others is parked again', async () => {
  const budget = new ContextBudget({ maxLive: 1 });
  const a = book(budget);
  a.lease.dispose();
  a.lease.dispose();
  assert.equal(a.canvas.gl.lost, true);
  assert.equal(budget.liveCount, 0);

  const b = book(budget);
  // Lost by accident (a GPU reset): the budget then parks it without losing it twice.
  b.canvas.extension.loseContext();
  await tasks();
  const c = book(budget);
  assert.equal(b.lease.state, 'parked');
  assert.deepEqual(b.canvas.calls, ['lose']);
  // Someone else restores it: it hands the context back again.
  b.canvas.extension.restoreContext();
  await tasks(6);
  assert.equal(b.canvas.gl.lost, true);
  assert.deepEqual(b.canvas.calls, ['lose', 'restore', 'lose']);
  assert.equal(c.lease.state, 'live');
});

test('node: a book parked while in view takes a context back once another book reports it is out of view, or lets go (no scroll needed)', async () => {
  const budget = new ContextBudget({ maxLive: 2 });
  // New books count as visible until their first report: the third admitted parks the first, in view.
  const a = book(budget);
  setVisible(a.lease, true);  // its report comes before it is parked: nothing changes for it later
  const b = book(budget);
  const c = book(budget);
  assert.equal(a.lease.state, 'parked');
  await tasks();
  setVisible(b.lease, true);
  assert.equal(a.lease.state, 'parked', 'every live book is in view: the budget is full');
  setVisible(c.lease, false);
  assert.equal(a.lease.state, 'restoring', 'the book out of view gave way');
  assert.equal(c.lease.state, 'parked');
  await tasks(6);
  assert.equal(a.lease.state, 'live');
  assert.equal(budget.liveCount, 2);

  // A live book destroyed: a parked book in view takes the freed context.
  const full = new ContextBudget({ maxLive: 1 });
  const x = book(full);
  setVisible(x.lease, true);
  const y = book(full);  // parks x, in view
  setVisible(y.lease, true);
  assert.equal(x.lease.state, 'parked', 'the one context is held by a book in view');
  await tasks();
  y.lease.dispose();
  assert.equal(x.lease.state, 'restoring');
  assert.equal(full.liveCount, 1);
});
