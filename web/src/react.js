'use client';
// conecurl/react: <Flipbook> for React 18 and 19. Props are the book's options and apply while it runs
// (book-mount.js); children can be the pages; a typed ref and useFlipbook() reach it. Nothing here needs
// a DOM until the component is mounted, so it renders on a server as a sized, empty box.
import {
  Children, createElement, forwardRef, isValidElement, useCallback, useEffect, useImperativeHandle, useMemo,
  useRef, useState,
} from 'react';
import { createPortal } from 'react-dom';
import { BookMount } from './components/book-mount.js';
import { BOX_STYLE } from './components/book-box.js';
import { EVENT_HANDLERS, pageBoxes } from './components/framework-props.js';

// Pages from children: an <img> is an image page ({ src, alt }); any other element is an HTML page,
// rendered by React into a box of its own (a portal) that the book lays over the page's place.
function pagesFromChildren(children, boxes) {
  const pages = [];
  const portals = [];
  const keys = new Set();
  for (const child of Children.toArray(children)) {
    if (!isValidElement(child)) continue;
    if (child.type === 'img') {
      const { src, alt } = child.props;
      pages.push(alt ? { src, alt } : src);
      continue;
    }
    const box = boxes.box(child.key);
    keys.add(child.key);
    pages.push(box);
    portals.push(createPortal(child, box, child.key));
  }
  boxes.keep(keys);
  return { pages, portals };
}

export const Flipbook = forwardRef(function Flipbook(props, ref) {
  const { children, className, style, id } = props;
  const latest = useRef(props);
  latest.current = props;
  const [mount] = useState(() => new BookMount(
    (type, event) => {
      const handler = latest.current[EVENT_HANDLERS[type]];
      if (handler) handler(event);
      else if (type === 'error') console.error(event.detail.error);
    },
    (page) => latest.current.onPageChange?.(page),
  ));
  const container = useRef(null);
  const [boxes] = useState(pageBoxes);
  const [mounted, setMounted] = useState(false);
  useEffect(() => setMounted(true), []);

  // Children are rendered into their page boxes only in the browser, once mounted (a server has no DOM).
  const fromChildren = mounted && props.pages === undefined && props.pdf === undefined && props.document === undefined;
  const { pages, portals } = fromChildren ? pagesFromChildren(children, boxes) : { pages: props.pages, portals: [] };
  const bookProps = useRef(null);
  bookProps.current = { ...props, pages };  // BookMount reads the options, page and defaultPage from it

  useEffect(() => {
    if (!mounted) return undefined;
    mount.mount(container.current, bookProps.current);
    return () => mount.unmount();
  }, [mounted, mount]);
  useEffect(() => { if (mounted) mount.update(bookProps.current); });

  useImperativeHandle(ref, () => mount.handle, [mount]);
  // The box the book fills, as <cone-flipbook> sizes itself (book-box.js); the `style` prop overrides any of it.
  return createElement('div', { ref: container, id, className, style: { ...BOX_STYLE, ...style } }, ...portals);
});

/**
 * State and calls of a <Flipbook> placed anywhere: pass `ref={flipbook.ref}` to it, then read
 * flipbook.page, pageCount, ready, display and call next(), prev(), flip(i), setZoom(s) from any control.
 */
export function useFlipbook() {
  const [state, setState] = useState({ ready: false, page: 0, pageCount: 0, display: null });
  const handle = useRef(null);
  const unsubscribe = useRef(null);
  const ref = useCallback((next) => {
    unsubscribe.current?.();
    unsubscribe.current = null;
    handle.current = next;
    if (next) unsubscribe.current = next.subscribe(setState);
  }, []);
  const calls = useMemo(() => {
    const call = (name) => (...args) => (handle.current ? handle.current[name](...args)
      : Promise.reject(new Error('conecurl: useFlipbook(): no <Flipbook ref={flipbook.ref}> is mounted')));
    return {
      next: call('next'),
      prev: call('prev'),
      flip: call('flip'),
      setZoom: (scale) => { if (handle.current) handle.current.zoom = scale; },
    };
  }, []);
  return { ...state, ...calls, ref, get book() { return handle.current?.book ?? null; } };
}
