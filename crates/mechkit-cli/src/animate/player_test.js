// A test of player.js under node, with a stand-in for the page (`node player_test.js
// PAGE.html`): the player draws the first frame, starts playing and its frames advance;
// pause stops them; seek shows a frame and its time; the button toggles; playback loops.
'use strict';

const fs = require('fs');
const assert = require('assert');

const page = fs.readFileSync(process.argv[2], 'utf8');
const data = page.match(/id="mechkit-data">([\s\S]*?)<\/script>/)[1];
const script = page.match(/<script>\n([\s\S]*?)<\/script>/)[1];

const texts = [];
const arcs = [];
// a 2D context that records the text and circles drawn and accepts everything else
const context = new Proxy(
  {
    fillText: (s) => texts.push(s),
    arc: (x, y, r) => arcs.push([x, y, r]),
  },
  {
    get: (target, key) => (key in target ? target[key] : () => {}),
    set: () => true,
  }
);

function element(properties) {
  const listeners = {};
  return Object.assign(
    {
      style: {},
      textContent: '',
      setAttribute() {},
      addEventListener(type, f) {
        listeners[type] = f;
      },
      fire(type) {
        listeners[type]();
      },
    },
    properties
  );
}

const elements = {
  'mechkit-data': element({ textContent: data }),
  scene: element({ getContext: () => context }),
  play: element({}),
  slider: element({ value: '0' }),
  time: element({}),
};
const document = { getElementById: (id) => elements[id] };
const window = {
  devicePixelRatio: 2,
  performance,
  // as in a browser, the timestamp a frame gets may precede the call that asked for it (the
  // player once stopped on the negative time this gave right after play())
  requestAnimationFrame: (f) => {
    const frameStart = performance.now() - 5;
    return setTimeout(() => f(frameStart), 10);
  },
  cancelAnimationFrame: (id) => clearTimeout(id),
};

new Function('window', 'document', script)(window, document);
const player = window.mechkitPlayer;

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

(async () => {
  assert.strictEqual(player.frames, 30);
  assert.strictEqual(player.frame(), 0);
  assert.ok(player.playing(), 'it starts playing');
  assert.ok(texts.includes('t = 0.000 s'), 'the time stamp of frame 0');
  assert.ok(texts.includes('Ball on a circle'), 'the title');
  assert.ok(texts.includes('0.5 m') && texts.includes('K'), 'the scale bar and the bars');
  assert.strictEqual(elements.scene.width, 1280, 'drawn for the device pixels');
  const ball = arcs.find((a) => Math.abs(a[2] - 16) < 1e-9);
  assert.ok(ball, 'a ball of 0.1 m at 160 px/m');
  assert.ok(Math.abs(ball[0] - 353.137) < 0.01 && Math.abs(ball[1] - 126.863) < 0.01, 'y up');

  await sleep(300);
  const advanced = player.frame();
  assert.ok(advanced > 0, 'the frames advance at 25 fps: ' + advanced);
  assert.strictEqual(elements.slider.value, String(advanced));

  player.pause();
  assert.ok(!player.playing());
  const held = player.frame();
  await sleep(150);
  assert.strictEqual(player.frame(), held, 'paused');
  assert.strictEqual(elements.play.textContent, 'Play');

  player.seek(15);
  assert.strictEqual(player.frame(), 15);
  assert.strictEqual(elements.time.textContent, 't = 0.600 s');
  player.seek(99);
  assert.strictEqual(player.frame(), 29, 'the last frame');

  elements.play.fire('click');
  assert.ok(player.playing(), 'the button plays');
  await sleep(200);
  assert.ok(player.frame() < 29, 'it loops: ' + player.frame());
  elements.slider.value = '7';
  elements.slider.fire('input');
  assert.ok(!player.playing(), 'the slider pauses');
  assert.strictEqual(player.frame(), 7);
  console.log('player ok');
})().catch((e) => {
  console.error(e);
  process.exit(1);
});
