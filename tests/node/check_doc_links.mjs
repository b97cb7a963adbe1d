// The link checker of README.md and docs/*.md: every relative link (and image) names a file of
// the repository that exists, and a #fragment a heading of the file it points to (GitHub's
// anchors); no link and no written path leaves the repository (`../shared/...`); the README,
// a newcomer's first page, names no issue numbers and no generator history either.
// Usage: node check_doc_links.mjs REPOSITORY_ROOT. Exits 1 listing every fault.
import fs from "node:fs";
import path from "node:path";

const root = path.resolve(process.argv[2] ?? ".");
// docs/realism.md is the realism study's record, kept by that work; its `../shared` mentions are
// the study's own scripts and data. Its links are still checked.
const textPathsAllowed = new Set(["docs/realism.md"]);

const faults = [];
const fault = (file, line, message) => faults.push(`${file}:${line}: ${message}`);

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens, and -1,
/// -2, ... for repeats.
function anchorsOf(text) {
  const anchors = new Set();
  const seen = new Map();
  let fenced = false;
  for (const line of text.split("\n")) {
    if (/^\s*```/.test(line)) fenced = !fenced;
    const heading = !fenced && /^#{1,6}\s+(.*?)\s*#*\s*$/.exec(line);
    if (!heading) continue;
    const plain = heading[1].replace(/`/g, "").replace(/\[([^\]]*)\]\([^)]*\)/g, "$1");
    const slug = plain.toLowerCase().replace(/[^\p{L}\p{N}\s_-]/gu, "").replace(/\s/g, "-");
    const count = seen.get(slug) ?? 0;
    seen.set(slug, count + 1);
    anchors.add(count === 0 ? slug : `${slug}-${count}`);
  }
  return anchors;
}

/// The lines of a Markdown file outside fenced code blocks, with inline code blanked.
function proseLines(text) {
  let fenced = false;
  return text.split("\n").map((line) => {
    if (/^\s*```/.test(line)) {
      fenced = !fenced;
      return "";
    }
    return fenced ? "" : line.replace(/`[^`]*`/g, (code) => " ".repeat(code.length));
  });
}

function checkFile(relative) {
  const file = path.join(root, relative);
  const text = fs.readFileSync(file, "utf8");
  const lines = text.split("\n");
  const prose = proseLines(text);
  let links = 0;
  prose.forEach((line, i) => {
    for (const match of line.matchAll(/!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g)) {
      ++links;
      const target = match[1];
      if (/^[a-z][a-z0-9+.-]*:/i.test(target)) continue; // http:, https:, mailto:
      const [where, fragment] = target.split("#");
      const resolved = where ? path.resolve(path.dirname(file), decodeURI(where)) : file;
      if (resolved !== root && !resolved.startsWith(root + path.sep)) {
        fault(relative, i + 1, `link '${target}' leaves the repository`);
        continue;
      }
      if (!fs.existsSync(resolved)) {
        fault(relative, i + 1, `dead link '${target}': no ${path.relative(root, resolved)}`);
        continue;
      }
      if (fragment && resolved.endsWith(".md") &&
          !anchorsOf(fs.readFileSync(resolved, "utf8")).has(fragment))
        fault(relative, i + 1, `dead link '${target}': no heading #${fragment} there`);
    }
  });
  // Paths outside the repository written as text (in code or prose).
  if (!textPathsAllowed.has(relative))
    lines.forEach((line, i) => {
      if (/(^|[\s`'"(])\.\.\/shared\b/.test(line))
        fault(relative, i + 1, `names a path outside the repository: ${line.trim()}`);
    });
  return links;
}

const files = ["README.md", ...fs.readdirSync(path.join(root, "docs"))
  .filter((name) => name.endsWith(".md")).sort().map((name) => `docs/${name}`)];
let links = 0;
for (const file of files) links += checkFile(file);

// The README is a first contact: no path above the repository, no issue numbers, no history.
const readme = fs.readFileSync(path.join(root, "README.md"), "utf8").split("\n");
readme.forEach((line, i) => {
  if (/\.\.\//.test(line)) fault("README.md", i + 1, `a path outside the repository: ${line.trim()}`);
  if (/\bissues?\s+#?\d+|#\d{1,4}\b/i.test(line))
    fault("README.md", i + 1, `an issue number: ${line.trim()}`);
  if (/\bgenerator (version )?\d+\b|\bseed 0\d\d\b/i.test(line))
    fault("README.md", i + 1, `generator history: ${line.trim()}`);
});

if (links < 50) fault("README.md", 0, `only ${links} links found: is the checker reading the files?`);
if (faults.length) {
  console.error(faults.join("\n"));
  console.error(`${faults.length} fault(s) in ${files.length} files`);
  process.exit(1);
}
console.log(`${links} links in ${files.length} files: none dead, none outside the repository`);
