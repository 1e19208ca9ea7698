// Types of the page loader (page-loader.js). Kept beside page-loader.js.
import type { PageErrorReason, PageSource } from '../book/flipbook.js';

/** Why a page could not be shown; `reason` says which kind of failure it was. */
export class PageLoadError extends Error {
  readonly name: 'PageLoadError';
  readonly reason: Exclude<PageErrorReason, 'upload'>;
  /** The HTTP status, for reason 'http'. */
  readonly status?: number;
  /** The URL that failed, where there was one. */
  readonly url?: string;
}

/**
 * Loads a page source into an image: URLs are fetched with CORS and decoded; images and canvases are
 * checked to be readable (not cross-origin without CORS). `owned` images were made by the loader.
 */
export function loadPage(source: PageSource, options?: {
  index?: number; size?: { width: number; height: number }; signal?: AbortSignal;
}): Promise<{ image: ImageBitmap | HTMLImageElement | HTMLCanvasElement; owned: boolean }>;
