// export_ifc.mjs READER DB RUN OPTION MODEL.ifc [NAME]: an option's IFC4
// model read back by web-ifc (tests/ifc, not Facet) against the store read
// by the sqlite3 program. Prints one "ok - ..." or "not ok - ..." line per
// check; exits 1 when one failed, 2 when the reader cannot run.
//
// The truth: a single surface's option has its panels in the panels table,
// panel by panel; a building's has each surface's counts, areas, costs,
// largest deviation and moulds in option_surfaces; both have their
// totals in the options row, in the units docs/store.md gives (deviation in
// m, shown in mm). Each plate's area is measured here from the
// coordinates of its IfcTriangulatedFaceSet (as written, in double), and
// again from the mesh web-ifc's geometry engine makes of it (in float).
// NAME: the surface's name as the model must hold it (a single surface).
import { createRequire } from 'module';
import { execFileSync } from 'child_process';
import { readFileSync } from 'fs';
import { join } from 'path';

const [reader, db, runText, optionText, model, wantName] =
    process.argv.slice(2);
const run = Number(runText), option = Number(optionText);
let W;
try {
    W = createRequire(join(reader, 'package.json'))('web-ifc');
} catch (e) {
    console.log(`not ok - web-ifc loads from ${reader} (${e.message})`);
    process.exit(2);
}

let failed = 0;
function check(name, ok, detail) {
    if (!ok)
        failed++;
    console.log((ok ? 'ok - ' : 'not ok - ') + name +
                (ok ? '' : '  (' + JSON.stringify(detail ?? '').slice(0, 300) +
                 ')'));
}
function close(a, b, rel) {
    if (a === null || b === null || a === undefined || b === undefined)
        return (a ?? null) === (b ?? null);
    return Math.abs(a - b) <= rel * Math.max(1, Math.abs(a), Math.abs(b));
}
function sql(query) {
    const out = execFileSync('sqlite3', ['-json', db, query],
                             { encoding: 'utf8' });
    return out.trim() ? JSON.parse(out) : [];
}

const api = new W.IfcAPI();
await api.Init();
const id = api.OpenModel(new Uint8Array(readFileSync(model)));
check('web-ifc opens the model as IFC4', id >= 0 &&
      api.GetModelSchema(id) === 'IFC4', api.GetModelSchema(id));

const ids = type => {
    const v = api.GetLineIDsWithType(id, type), out = [];
    for (let k = 0; k < v.size(); k++)
        out.push(v.get(k));
    return out;
};
const line = n => api.GetLine(id, n);
const ref = r => (r && r.type === 5 ? r.value : null);
// A measure's value from its text, in double: web-ifc keeps the text.
const num = v => v === null || v === undefined ? null
    : typeof v._internalValue === 'string' ? Number(v._internalValue)
    : v._internalValue !== undefined ? Number(v._internalValue)
    : typeof v.value === 'number' ? v.value : Number(v.value);
const text = v => v === null || v === undefined ? null : v.value;

const building = sql(`SELECT count(*) AS n FROM surfaces WHERE run=${run}`)
    [0].n > 0;
const row = sql(`SELECT * FROM options WHERE run=${run} AND number=${option}`)
    [0];

// The spatial structure: project, site, building, storey, aggregated in
// that order; the curtain walls in the storey.
const one = {};
for (const [name, type] of [['project', W.IFCPROJECT], ['site', W.IFCSITE],
                            ['building', W.IFCBUILDING],
                            ['storey', W.IFCBUILDINGSTOREY]])
    one[name] = ids(type);
check('one project, site, building and storey',
      Object.values(one).every(v => v.length === 1),
      Object.fromEntries(Object.entries(one).map(([k, v]) => [k, v.length])));
const aggregates = ids(W.IFCRELAGGREGATES).map(line);
const partsOf = whole => aggregates
    .filter(a => ref(a.RelatingObject) === whole)
    .flatMap(a => a.RelatedObjects.map(ref));
check('project > site > building > storey (IfcRelAggregates)',
      JSON.stringify(partsOf(one.project[0])) === JSON.stringify(one.site) &&
      JSON.stringify(partsOf(one.site[0])) ===
          JSON.stringify(one.building) &&
      JSON.stringify(partsOf(one.building[0])) ===
          JSON.stringify(one.storey));
const project = line(one.project[0]);
const units = line(ref(project.UnitsInContext)).Units.map(u => line(ref(u)));
check('the project\'s length unit is the metre',
      units.some(u => u.UnitType?.value === 'LENGTHUNIT' &&
                 u.Name?.value === 'METRE' && u.Prefix === null), units);

const walls = ids(W.IFCCURTAINWALL);
const contained = ids(W.IFCRELCONTAINEDINSPATIALSTRUCTURE).map(line);
const inStorey = contained
    .filter(c => ref(c.RelatingStructure) === one.storey[0])
    .flatMap(c => c.RelatedElements.map(ref));
check('every curtain wall is in the storey',
      walls.length > 0 && JSON.stringify(inStorey) === JSON.stringify(walls),
      [walls, inStorey]);

// The surfaces as the store has them, in order.
let surfaces;
if (building) {
    surfaces = sql(`SELECT s.name, o.* FROM option_surfaces o JOIN surfaces s
        ON s.run = o.run AND s.surface = o.surface
        WHERE o.run=${run} AND o.option=${option} ORDER BY o.surface`);
} else {
    const stored = sql(`SELECT count(*) AS n FROM panels
        WHERE run=${run} AND option=${option}`)[0].n;
    check(`the store holds the option's ${row.panels} panels`,
          stored === row.panels, stored);
    surfaces = [{ name: wantName, panels: stored }];
}
const wallNames = walls.map(w => text(line(w).Name));
check(`one curtain wall per surface (${surfaces.length}), named as the ` +
      'surfaces', JSON.stringify(wallNames) ===
          JSON.stringify(surfaces.map(s => s.name)),
      [wallNames, surfaces.map(s => s.name)]);

// Plates per wall, against the store.
const plates = ids(W.IFCPLATE);
const plateOf = new Map(plates.map(p => [p, line(p)]));
const perWall = walls.map(w => partsOf(w));
check(`IfcPlate per curtain wall as the store's panels per surface`,
      JSON.stringify(perWall.map(p => p.length)) ===
          JSON.stringify(surfaces.map(s => s.panels)),
      [perWall.map(p => p.length), surfaces.map(s => s.panels)]);
const aggregated = perWall.flat();
check(`every plate (${plates.length}) in one curtain wall, ` +
      `${row.panels} in all`, plates.length === row.panels &&
      aggregated.length === plates.length &&
      new Set(aggregated).size === plates.length &&
      aggregated.every(p => plateOf.has(p)), [plates.length, row.panels]);
check('every plate a CURTAIN_PANEL',
      plates.every(p => plateOf.get(p).PredefinedType?.value ===
                   'CURTAIN_PANEL'));

// Property sets: one 'Facet_Panel' per plate.
const setOf = new Map();
for (const r of ids(W.IFCRELDEFINESBYPROPERTIES).map(line)) {
    const set = line(ref(r.RelatingPropertyDefinition));
    if (text(set.Name) !== 'Facet_Panel')
        continue;
    const values = {};
    for (const h of set.HasProperties) {
        const p = line(ref(h));
        values[text(p.Name)] = p.NominalValue;
    }
    for (const o of r.RelatedObjects)
        setOf.set(ref(o), (setOf.get(ref(o)) ?? []).concat([values]));
}
check('one Facet_Panel property set per plate',
      plates.every(p => (setOf.get(p) ?? []).length === 1),
      plates.filter(p => (setOf.get(p) ?? []).length !== 1).slice(0, 3));
const props = p => (setOf.get(p) ?? [{}])[0];

// The units the values are in: Deviation in mm, Cost in USD, Area in the
// project's (m^2).
const unitOf = { Deviation: new Set(), Cost: new Set(), Area: new Set(),
                 CornerDistance: new Set(), CornerMoved: new Set() };
for (const n of ids(W.IFCPROPERTYSINGLEVALUE)) {
    const p = line(n), name = text(p.Name);
    if (!(name in unitOf))
        continue;
    const u = ref(p.Unit) === null ? null : line(ref(p.Unit));
    unitOf[name].add(u === null ? 'project'
        : u.Currency ? 'currency ' + text(u.Currency)
        : (u.Prefix?.value ?? '') + ' ' + u.Name?.value);
}
check('Deviation, CornerDistance and CornerMoved in mm, Cost in USD, ' +
      'Area in the project\'s unit',
      [...unitOf.Deviation].join() === 'MILLI METRE' &&
      [...unitOf.CornerDistance].join() === 'MILLI METRE' &&
      [...unitOf.CornerMoved].join() === 'MILLI METRE' &&
      [...unitOf.Cost].join() === 'currency USD' &&
      [...unitOf.Area].join() === 'project' &&
      units.some(u => u.UnitType?.value === 'AREAUNIT' &&
                 u.Name?.value === 'SQUARE_METRE' && u.Prefix === null),
      Object.fromEntries(Object.entries(unitOf).map(([k, v]) => [k, [...v]])));

// Panel ids 1..N in the order of the walls, each the plate's Name and Tag.
const numbers = aggregated.map(p => text(props(p).PanelId));
check('panel ids 1..N across the building, each the plate\'s Name and Tag',
      numbers.every((n, k) => n === String(k + 1) &&
                    text(plateOf.get(aggregated[k]).Name) === n &&
                    text(plateOf.get(aggregated[k]).Tag) === n),
      numbers.slice(0, 5));

// With IDS_OUT set, each plate's id, surface, column and row, as web-ifc
// reads them, for the caller to hold against the other formats' ids.
if (process.env.IDS_OUT) {
    const { writeFileSync } = await import('fs');
    writeFileSync(process.env.IDS_OUT, aggregated.map(p => {
        const v = props(p);
        return [text(v.PanelId), text(v.Surface), num(v.ColumnI),
                num(v.RowJ)].join(',');
    }).join('\n') + '\n');
}

// GlobalIds: unique, 22 characters of IFC's base 64.
const gids = [];
for (const type of [W.IFCPROJECT, W.IFCSITE, W.IFCBUILDING,
                    W.IFCBUILDINGSTOREY, W.IFCCURTAINWALL, W.IFCPLATE,
                    W.IFCRELAGGREGATES, W.IFCRELCONTAINEDINSPATIALSTRUCTURE,
                    W.IFCRELDEFINESBYPROPERTIES, W.IFCPROPERTYSET])
    for (const n of ids(type))
        gids.push(text(line(n).GlobalId));
check(`${gids.length} GlobalIds, unique, each 22 characters of IFC base 64`,
      new Set(gids).size === gids.length &&
      gids.every(g => /^[0-3][0-9A-Za-z_$]{21}$/.test(g)),
      gids.filter(g => !/^[0-3][0-9A-Za-z_$]{21}$/.test(g)).slice(0, 3));

// Each plate's area from its IfcTriangulatedFaceSet's coordinates.
function triangleArea(a, b, c) {
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
          z = u[0] * v[1] - u[1] * v[0];
    return Math.sqrt(x * x + y * y + z * z) / 2;
}
function faceSetArea(plate) {
    const shape = ref(plate.Representation);
    if (shape === null)
        return 0;
    let area = 0;
    for (const r of line(shape).Representations.map(x => line(ref(x)))) {
        if (text(r.RepresentationIdentifier) !== 'Body' ||
            text(r.RepresentationType) !== 'Tessellation')
            return NaN;
        for (const item of r.Items.map(x => line(ref(x)))) {
            const points = line(ref(item.Coordinates)).CoordList
                .map(p => p.map(num));
            for (const t of item.CoordIndex) {
                const [a, b, c] = t.map(k => points[num(k) - 1]);
                area += triangleArea(a, b, c);
            }
        }
    }
    return area;
}
// The same from web-ifc's mesh of the plate (float: to 1e-4).
function meshArea(plate) {
    const mesh = api.GetFlatMesh(id, plate);
    let area = 0;
    for (let g = 0; g < mesh.geometries.size(); g++) {
        const placed = mesh.geometries.get(g);
        const geometry = api.GetGeometry(id, placed.geometryExpressID);
        const v = api.GetVertexArray(geometry.GetVertexData(),
                                     geometry.GetVertexDataSize());
        const ix = api.GetIndexArray(geometry.GetIndexData(),
                                     geometry.GetIndexDataSize());
        const m = placed.flatTransformation;
        const at = k => {
            const x = v[6 * k], y = v[6 * k + 1], z = v[6 * k + 2];
            return [m[0] * x + m[4] * y + m[8] * z + m[12],
                    m[1] * x + m[5] * y + m[9] * z + m[13],
                    m[2] * x + m[6] * y + m[10] * z + m[14]];
        };
        for (let t = 0; t + 2 < ix.length; t += 3)
            area += triangleArea(at(ix[t]), at(ix[t + 1]), at(ix[t + 2]));
        if (typeof geometry.delete === "function")
            geometry.delete();
    }
    if (typeof mesh.delete === "function")
        mesh.delete();
    return area;
}
const area = new Map(plates.map(p => [p, faceSetArea(plateOf.get(p))]));
let bad = plates.filter(p => !close(area.get(p), num(props(p).Area), 1e-6));
check('each plate\'s face set has the area its Area property says (1e-6)',
      bad.length === 0, bad.slice(0, 3).map(p => [area.get(p),
                                                    num(props(p).Area)]));
bad = plates.filter(p => !close(meshArea(p), area.get(p), 1e-4));
check('web-ifc\'s mesh of each plate has its face set\'s area (1e-4, float)',
      bad.length === 0, bad.slice(0, 3));

// The corner move (issue 33). A classified option's plates (and a
// building's) have CornerDistance and CornerMoved without a value: not
// measured, never 0. A planarized option's moved panel is its moved quad:
// its face set's four points are the stored corners, planar to the
// option's reported planarity, and its CornerDistance is the distance of
// those points to the surface's triangles, measured here by brute force
// (Ericson's closest point on a triangle, over every triangle of the OBJ
// named by PLANAR_MESH).
const vsub = (u, v) => [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
const vdot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
const vcross = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                          u[0] * v[1] - u[1] * v[0]];
const vlen = u => Math.sqrt(vdot(u, u));
const along = (a, d, t) => [a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]];
function closestOnTriangle(p, a, b, c) {
    const ab = vsub(b, a), ac = vsub(c, a), ap = vsub(p, a);
    const d1 = vdot(ab, ap), d2 = vdot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const bp = vsub(p, b), d3 = vdot(ab, bp), d4 = vdot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return along(a, ab, d1 / (d1 - d3));
    const cp = vsub(p, c), d5 = vdot(ab, cp), d6 = vdot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return along(a, ac, d2 / (d2 - d6));
    const va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return along(b, vsub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const v = vb / (va + vb + vc), w = vc / (va + vb + vc);
    return along(along(a, ab, v), ac, w);
}
function readTriangles(path) {
    const v = [], t = [];
    for (const l of readFileSync(path, 'utf8').split('\n')) {
        const w = l.trim().split(/\s+/);
        if (w[0] === 'v')
            v.push(w.slice(1, 4).map(Number));
        else if (w[0] === 'f') {
            const k = w.slice(1).map(x => v[Number(x.split('/')[0]) - 1]);
            for (let m = 1; m + 1 < k.length; m++)
                t.push([k[0], k[m], k[m + 1]]);
        }
    }
    return t;
}
const meshDistance = (p, triangles) => Math.min(...triangles.map(
    ([a, b, c]) => vlen(vsub(p, closestOnTriangle(p, a, b, c)))));
function facePoints(plate) {
    const shape = ref(plate.Representation);
    if (shape === null)
        return [];
    return line(shape).Representations.map(x => line(ref(x)))
        .flatMap(r => r.Items.map(x => line(ref(x))))
        .flatMap(item => line(ref(item.Coordinates)).CoordList
                         .map(p => p.map(num)));
}
const cornerNumbers = p => [props(p).CornerDistance, props(p).CornerMoved];
check('every plate has CornerDistance and CornerMoved in its property set',
      plates.every(p => 'CornerDistance' in props(p) &&
                   'CornerMoved' in props(p)));
if (building || !row.planarized) {
    bad = plates.filter(p => cornerNumbers(p).some(v => v !== null &&
                                                   v !== undefined));
    check('a classified option moved no corner: CornerDistance and ' +
          'CornerMoved without a value on every plate (never 0)',
          bad.length === 0, bad.slice(0, 3).map(p => cornerNumbers(p)));
} else {
    const stored = new Map(sql(`SELECT * FROM panels WHERE run=${run} AND
        option=${option}`).map(r => [`${r.i},${r.j}`, r]));
    const triangles = process.env.PLANAR_MESH
        ? readTriangles(process.env.PLANAR_MESH) : null;
    let moved = 0;
    const wrongQuad = [], wrongFlat = [], wrongValue = [], wrongFar = [];
    for (const p of plates) {
        const v = props(p), s = stored.get(`${num(v.ColumnI)},${num(v.RowJ)}`);
        const [distance, move] = cornerNumbers(p).map(num);
        if (!s || s.corner_distance === null) {
            if (distance !== null || move !== null)
                wrongValue.push([text(v.PanelId), distance, move]);
            continue;
        }
        moved++;
        if (!close(distance, s.corner_distance * 1000, 1e-12) ||
            !close(move, s.corner_moved * 1000, 1e-12))
            wrongValue.push([text(v.PanelId), distance, move,
                             s.corner_distance, s.corner_moved]);
        const q = facePoints(plateOf.get(p));
        const corners = [0, 1, 2, 3].map(c => ['x', 'y', 'z'].map(
            x => s[`c${c}_${x}`]));
        if (q.length !== 4 || !q.every(x => corners.some(
                c => vlen(vsub(x, c)) <= 1e-12 * Math.max(1, vlen(c))))) {
            wrongQuad.push([text(v.PanelId), q.length]);
            continue;
        }
        const d1 = vsub(q[2], q[0]), d2 = vsub(q[3], q[1]), n = vcross(d1, d2);
        const relative = Math.abs(vdot(vsub(q[1], q[0]), n)) / vlen(n) /
                         Math.max(vlen(d1), vlen(d2));
        if (!(relative <= row.planarity_reached * (1 + 1e-9) + 1e-12) ||
            (s.built_type === 'FP' && !(relative <= 1e-3)))
            wrongFlat.push([text(v.PanelId), relative, row.planarity_reached]);
        if (triangles) {
            const brute = Math.max(...q.map(x => meshDistance(x, triangles)));
            if (!(Math.abs(brute * 1000 - distance) <= 1e-6))
                wrongFar.push([text(v.PanelId), distance, brute * 1000]);
        }
    }
    check(`a planarized option: each moved plate's body is its moved quad, ` +
          `the four stored corners (${moved} plates)`, moved > 0 &&
          wrongQuad.length === 0, wrongQuad.slice(0, 3));
    check('each moved quad planar within the option\'s reported planarity ' +
          `${row.planarity_reached} (and 1e-3 when FP)`,
          wrongFlat.length === 0, wrongFlat.slice(0, 3));
    check('CornerDistance and CornerMoved (mm) as the panels table; none ' +
          'on a plate not moved', wrongValue.length === 0,
          wrongValue.slice(0, 3));
    if (triangles)
        check('CornerDistance the brute-force distance of the quad\'s ' +
              'corners to the surface\'s triangles (1e-6 mm)',
              wrongFar.length === 0, wrongFar.slice(0, 3));
}

const USD = 0.005;
if (!building) {
    // Panel by panel against the panels table.
    const stored = new Map(sql(`SELECT * FROM panels WHERE run=${run} AND
        option=${option}`).map(r => [`${r.i},${r.j}`, r]));
    const seen = new Set();
    const wrong = [];
    for (const p of plates) {
        const v = props(p);
        const key = `${num(v.ColumnI)},${num(v.RowJ)}`;
        const s = stored.get(key);
        seen.add(key);
        if (!s || text(v.TypeAsClassed) !== s.type ||
            text(v.TypeAsBuilt) !== s.built_type ||
            text(v.Class) !== s.class ||
            (v.MouldFamily ? num(v.MouldFamily) : null) !== s.mould_family ||
            !close(num(v.Deviation), s.deviation * 1000, 1e-9) ||
            !close(num(v.Area), s.area, 1e-12) ||
            !close(num(v.Cost), s.cost, 1e-12) ||
            text(v.Surface) !== wantName)
            wrong.push([key, v, s]);
    }
    check('each plate\'s type, class, mould, deviation, area, cost as the ' +
          'panels table', wrong.length === 0 && seen.size === stored.size,
          wrong[0]);
    bad = plates.filter(p => {
        const v = props(p), s = stored.get(`${num(v.ColumnI)},${num(v.RowJ)}`);
        return !s || !close(area.get(p), s.area, 1e-6);
    });
    check('each plate\'s geometry has its stored panel\'s area (1e-6)',
          bad.length === 0, bad.slice(0, 3).map(p => area.get(p)));
} else {
    // Surface by surface against option_surfaces.
    const wrong = [];
    surfaces.forEach((s, k) => {
        const mine = perWall[k].map(p => ({ v: props(p), area: area.get(p) }));
        // Counted by type as classed, as classify.c sums the totals (an SP
        // misfit is retyped DP unless the run types SP by class alone).
        for (const t of ['FP', 'SP', 'DP']) {
            const of = mine.filter(m => text(m.v.TypeAsClassed) === t);
            const sum = of.reduce((a, m) => a + num(m.v.Area), 0);
            const geometry = of.reduce((a, m) => a + m.area, 0);
            const want = s[t.toLowerCase() + '_area'];
            if (of.length !== s[t.toLowerCase() + '_count'] ||
                !close(sum, want, 1e-9) || !close(geometry, want, 1e-6))
                wrong.push([s.name, t, of.length, sum, geometry,
                            s[t.toLowerCase() + '_count'], want]);
        }
        const cost = mine.reduce((a, m) => a + num(m.v.Cost), 0);
        if (Math.abs(cost - s.area_cost) >= USD)
            wrong.push([s.name, 'cost', cost, s.area_cost]);
        // The largest deviation of a panel classed FP or SP (a DP panel
        // is moulded to the surface: classify.c's max_deviation).
        const worst = Math.max(0, ...mine
            .filter(m => text(m.v.TypeAsClassed) !== 'DP')
            .map(m => num(m.v.Deviation)));
        if (!close(worst, s.max_deviation * 1000, 1e-9))
            wrong.push([s.name, 'max deviation (mm)', worst,
                        s.max_deviation * 1000]);
        const moulds = new Set(mine.filter(m => m.v.MouldFamily)
                                   .map(m => num(m.v.MouldFamily)));
        if (moulds.size !== s.moulds_used)
            wrong.push([s.name, 'moulds used', moulds.size, s.moulds_used]);
        if (mine.some(m => text(m.v.Surface) !== s.name))
            wrong.push([s.name, 'Surface property']);
    });
    check('each surface\'s plates: count and area (properties 1e-9, ' +
          'geometry 1e-6) by type, cost to the cent, largest deviation ' +
          'and moulds used as option_surfaces',
          wrong.length === 0, wrong.slice(0, 3));
    const all = plates.map(props);
    const families = new Set(all.filter(v => v.MouldFamily)
                                .map(v => num(v.MouldFamily)));
    const classes = {};
    for (const v of all)
        classes[text(v.Class)] = (classes[text(v.Class)] ?? 0) + 1;
    const wrongClass = Object.entries(classes)
        .filter(([c, n]) => row[c + '_count'] !== n);
    check(`the building: ${row.moulds} mould families and the options ` +
          'row\'s count of each class', families.size === row.moulds &&
          wrongClass.length === 0, [families.size, row.moulds, wrongClass]);
}
api.CloseModel(id);
process.exit(failed ? 1 : 0);
