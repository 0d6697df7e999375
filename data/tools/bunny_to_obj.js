// Converts the Stanford bunny of the npm package `bunny` (public domain) to OBJ.
// Usage: npm pack bunny@1.0.1 && tar xzf bunny-1.0.1.tgz && node bunny_to_obj.js package/index.js bunny.obj
'use strict';
const fs = require('fs');
const path = require('path');
const bunny = require(path.resolve(process.argv[2]));
const lines = [
  '# Stanford bunny (Stanford 3D Scanning Repository), public domain.',
  '# Converted from npm package bunny@1.0.1 by data/tools/bunny_to_obj.js.',
  `# ${bunny.positions.length} vertices, ${bunny.cells.length} triangles`,
];
for (const p of bunny.positions) lines.push(`v ${p[0]} ${p[1]} ${p[2]}`);
for (const c of bunny.cells) lines.push(`f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}`);
fs.writeFileSync(process.argv[3], lines.join('\n') + '\n');
