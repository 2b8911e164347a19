// Converts the npm package "bunny" (the Stanford bunny, public domain, by Mikola Lysenko) into
// assets/bunny.obj. Run once by scripts/convert_bunny.sh; the result is committed.
//   node scripts/convert_bunny.js PACKAGE_DIR OUT.obj
const fs = require('fs');
const path = require('path');
const [packageDir, out] = process.argv.slice(2);
const bunny = require(path.resolve(packageDir));
const version = require(path.resolve(packageDir, 'package.json')).version;
let text = `# The Stanford bunny, from the npm package "bunny" ${version} (public domain).\n` +
    `# ${bunny.positions.length} vertices, ${bunny.cells.length} triangles; converted by ` +
    `scripts/convert_bunny.sh.\n`;
for (const p of bunny.positions) text += `v ${p[0]} ${p[1]} ${p[2]}\n`;
for (const c of bunny.cells) text += `f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}\n`;
fs.writeFileSync(out, text);
