// A failed scene's 3D view: its data is a script beside its images, loaded when the box opens.
function openView(box, then) {
  if (box.view) { if (then) then(box.view); return; }
  if (box.dataset.loading) return;
  box.dataset.loading = '1';
  const script = document.createElement('script');
  script.src = box.dataset.src;
  script.onload = () => {
    const data = window.raylabViewData && window.raylabViewData[box.dataset.view];
    if (!data) return;
    box.view = raylabView3d(box.querySelector('.view3d-root'), data);
    const first = data.trees.length > 0 ? data.trees[0].pixel : null;
    if (first) box.querySelector('.picked3d').textContent = 'Pixel (' + first.join(', ') +
      '): of the pixels the report holds trees for, the one that differs nearest the first that differs. ' +
      'Click the expected or your image to pick another.';
    if (then) then(box.view);
  };
  document.head.append(script);
}
for (const box of document.querySelectorAll('details[data-view]')) {
  box.addEventListener('toggle', () => { if (box.open) openView(box); });
}
const firstBox = document.querySelector('details[data-view]');
if (firstBox) firstBox.open = true;
for (const img of document.querySelectorAll('td[data-scene] img')) {
  img.addEventListener('click', (event) => {
    const rect = img.getBoundingClientRect();
    const x = Math.floor((event.clientX - rect.left) / rect.width * img.naturalWidth);
    const y = Math.floor((event.clientY - rect.top) / rect.height * img.naturalHeight);
    const cell = img.closest('td');
    const scene = cell.dataset.scene;
    const box = document.getElementById('picked');
    box.hidden = false;
    // A final picture is drawn at a fraction of its scene's size: the command draws it at its own.
    const size = 'final' in cell.dataset ? ' --size ' + img.naturalWidth + 'x' + img.naturalHeight : '';
    box.textContent = 'pixel (' + x + ', ' + y + '): cargo run -p grader -- render ' + scene + size + ' --tree ' + x + ',' + y +
      ' (add --view tree.html for its page in 3D)';
    const view = cell.querySelector('details[data-view]');
    if (view) {
      view.open = true;
      openView(view, (v) => {
        const at = v.pick(x, y);
        if (at) view.querySelector('.picked3d').textContent = 'Pixel (' + at.join(', ') +
          '), the grid pixel nearest your click (' + x + ', ' + y + '): the report holds the trees of one pixel in every ' +
          v.step + ' × ' + v.step + ' block.';
      });
    }
  });
}
