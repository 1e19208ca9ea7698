// The page, rendered on the server: a heading and the client component holding the book.
import BookDemo from './book-demo.js';

export default function Page() {
  return (
    <main>
      <h1 style={{ fontSize: 16, height: 30, margin: 0 }}>A flipbook in Next.js</h1>
      <BookDemo />
    </main>
  );
}
