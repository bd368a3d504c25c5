// End-to-end test of `mechkit serve` in headless Chromium (playwright-core; run by run.sh,
// which starts the server on a copy of examples/ and passes its URL):
// open the app, open bouncing_ball_floor.toml from the list, type a unit typo and see the
// error at that line (in the list and in the gutter), fix it and see the errors go, download
// the text, run it, see the plots and the animation, and check that the player's frames
// advance.
//
// Environment: MECHKIT_URL (the server), CHROMIUM (default /usr/bin/chromium),
// MECHKIT_SCREENSHOTS (a folder for serve_editor.png and serve_run.png; none if unset).
import {test} from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import {chromium} from 'playwright-core';

const url = process.env.MECHKIT_URL;
const shots = process.env.MECHKIT_SCREENSHOTS;
const FILE = 'bouncing_ball_floor.toml';
const MASS = 'mass     = "0.06 kg"';

async function screenshot(page, name) {
  if (shots) {
    await page.screenshot({path: path.join(shots, name)});
  }
}

test('the app edits, checks and runs a scenario', {timeout: 300_000}, async (t) => {
  assert.ok(url, 'MECHKIT_URL is the server to test');
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    // no GPU here, and no network beyond this machine to look for
    args: ['--disable-gpu', '--disable-quic'],
  });
  t.after(() => browser.close());
  const page = await browser.newPage({viewport: {width: 1480, height: 920}});
  const problems = [];
  page.on('pageerror', (e) => problems.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') {
      problems.push(`${m.text()} (${m.location().url})`);
    }
  });
  const editor = page.locator('#editor');

  let line = 0;
  await t.test('opens the example from the list', async () => {
    await page.goto(url);
    await page.locator(`#files li[data-path="${FILE}"]`).click();
    await assert.doesNotReject(page.waitForFunction(
      () => document.getElementById('editor').value.includes('restitution')));
    await page.locator('#status.ok').waitFor();
    assert.equal(await page.locator('#file-name').textContent(), FILE);
    assert.ok(await page.locator('#gallery li').count() > 0, 'the gallery is listed');
    const text = await editor.inputValue();
    line = text.split('\n').findIndex((l) => l.includes(MASS)) + 1;
    assert.ok(line > 0, `the example has the line ${MASS}`);
  });

  await t.test('shows a unit typo at its line', async () => {
    // the caret after "kg", then one more "g" typed
    await editor.evaluate((area, mass) => {
      const at = area.value.indexOf(mass) + mass.length - 1;
      area.focus();
      area.setSelectionRange(at, at);
    }, MASS);
    await page.keyboard.type('g');
    const error = page.locator('#errors li[data-line]');
    await error.first().waitFor();
    assert.equal(await error.count(), 1);
    assert.equal(await error.getAttribute('data-line'), String(line));
    const shown = await error.textContent();
    assert.match(shown, new RegExp(`^${line}:\\d+`), shown);
    assert.match(shown, /unknown unit `kgg`/, shown);
    assert.equal(await page.locator(`#gutter-lines div[data-line="${line}"]`).getAttribute('class'),
      'error');
    assert.ok(await page.locator('#run').isDisabled(), 'no run of an invalid scenario');
    await editor.evaluate((area) => area.scrollTo(0, 0));
    await screenshot(page, 'serve_editor.png');
  });

  await t.test('fixing it clears the errors', async () => {
    await page.keyboard.press('Backspace');
    await page.locator('#status.ok').waitFor();
    assert.equal(await page.locator('#errors li[data-line]').count(), 0);
    assert.equal(await page.locator('#gutter-lines .error').count(), 0);
    assert.ok((await editor.inputValue()).includes(MASS));
  });

  await t.test('downloads the text being edited', async () => {
    const [download] = await Promise.all([
      page.waitForEvent('download'),
      page.locator('#save').click(),
    ]);
    assert.equal(download.suggestedFilename(), FILE);
    const chunks = [];
    for await (const chunk of await download.createReadStream()) {
      chunks.push(chunk);
    }
    assert.equal(Buffer.concat(chunks).toString('utf8'), await editor.inputValue());
  });

  await t.test('a run shows its plots and animation', async () => {
    await page.locator('#run').click();
    await page.locator('#run-state.ok').waitFor({timeout: 120_000});
    const plots = page.locator('#plots img');
    assert.equal(await plots.count(), 4, 'y(t), vy(t), energy(t) and the energy bars');
    await page.waitForFunction(() => Array.from(document.querySelectorAll('#plots img'))
      .every((img) => img.complete && img.naturalWidth > 0));
    assert.ok(await plots.first().isVisible());
    const frame = page.locator('#animation');
    await frame.waitFor();
    await frame.scrollIntoViewIfNeeded();
    const player = await (await frame.elementHandle()).contentFrame();
    await player.waitForFunction(() => window.mechkitPlayer && window.mechkitPlayer.frames > 1);
    await player.evaluate(() => window.mechkitPlayer.seek(0));
    const before = await player.evaluate(() => window.mechkitPlayer.frame());
    await page.waitForTimeout(500);
    const after = await player.evaluate(() => window.mechkitPlayer.frame());
    assert.ok(await player.evaluate(() => window.mechkitPlayer.playing()));
    assert.ok(after > before, `the animation plays: frame ${before}, then ${after}`);
    const names = await page.locator('#downloads a').allTextContents();
    assert.ok(names.some((n) => n.startsWith('trajectory.csv')), names.join(', '));
    assert.ok(names.some((n) => n.startsWith('summary.json')), names.join(', '));
    // the GIF is drawn after the run, then listed
    await page.locator('#downloads a[download="animation.gif"]').waitFor({timeout: 180_000});
    await page.locator('.result-pane').evaluate((pane) => pane.scrollTo(0, 0));
    await editor.evaluate((area) => area.scrollTo(0, 0));
    // the picture: the ball in flight after its first bounce, its trail behind it
    await player.evaluate(() => window.mechkitPlayer.seek(Math.round(window.mechkitPlayer.frames * 0.3)));
    await screenshot(page, 'serve_run.png');
  });

  await t.test('the page logged no errors', () => {
    assert.deepEqual(problems, []);
  });
});
