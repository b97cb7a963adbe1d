// What every node check shares: failing with a message, and loading an npm decoder with a hint
// when it is missing.

/** Prints FAIL: `message` and exits 1. */
export function fail(message) {
  console.error(`FAIL: ${message}`);
  process.exit(1);
}

/** The module `name`, or fail() with how to install the test decoders. */
export async function load(name) {
  try {
    return await import(name);
  } catch (error) {
    fail(`cannot load ${name} (${error.message}).\nInstall the test decoders first: npm ci --prefix tests/node`);
  }
}
