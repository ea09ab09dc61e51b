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
const unitOf = { Deviation: new Set(), Cost: new Set(), Area: new Set() };
for (const n of ids(W.IFCPROPERTYSINGLEVALUE)) {
    const p = line(n), name = text(p.Name);
    if (!(name in unitOf))
        continue;
    const u = ref(p.Unit) === null ? null : line(ref(p.Unit));
    unitOf[name].add(u === null ? 'project'
        : u.Currency ? 'currency ' + text(u.Currency)
        : (u.Prefix?.value ?? '') + ' ' + u.Name?.value);
}
check('Deviation in mm, Cost in USD, Area in the project\'s unit',
      [...unitOf.Deviation].join() === 'MILLI METRE' &&
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
