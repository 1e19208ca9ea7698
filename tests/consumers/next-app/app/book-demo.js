'use client';
// A client component: <Flipbook> with a ref, a display held in state, and window hooks for the test.
import { useEffect, useRef, useState } from 'react';
import { Flipbook } from 'conecurl/react';

const pages = Array.from({ length: 6 }, (_, i) => `/pages/page-${i}.svg`);

export default function BookDemo() {
  const book = useRef(null);
  const [display, setDisplay] = useState('double');
  useEffect(() => {
    window.app = { book, setDisplay };
  }, []);
  return (
    <>
      <button id="next" onClick={() => book.current.next()}>Next</button>
      <Flipbook ref={book} id="book" pages={pages} display={display} defaultPage={0}
        style={{ width: 640, height: 400, aspectRatio: 'auto' }}
        onReady={() => { document.body.dataset.ready = 'true'; }}
        onError={(event) => { document.body.dataset.error = event.detail.error.message; }} />
    </>
  );
}
