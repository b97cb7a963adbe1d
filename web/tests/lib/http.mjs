// Plain HTTP GETs with node:http: the exact bytes and headers the server sent (fetch would ask
// for gzip and inflate it behind our back).
import { request } from 'node:http';

/** Resolves to { status, headers, body: Buffer } of GET `url` with `headers`. */
export function get(url, headers = {}) {
  return new Promise((resolve, reject) => {
    const req = request(url, { headers }, (response) => {
      const chunks = [];
      response.on('data', (chunk) => chunks.push(chunk));
      response.on('end', () => resolve({ status: response.statusCode, headers: response.headers, body: Buffer.concat(chunks) }));
      response.on('error', reject);
    });
    req.setTimeout(30_000, () => req.destroy(new Error(`GET ${url}: no answer in 30 s`)));
    req.on('error', reject);
    req.end();
  });
}

/** The body of a Buffer as its own ArrayBuffer (decoders index the whole .buffer from 0). */
export const arrayBufferOf = (buffer) => buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength);
