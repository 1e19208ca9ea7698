// Root layout of the Next.js consumer: a server component.
export const metadata = { title: 'conecurl in Next.js', icons: { icon: 'data:,' } };  // no favicon request

export default function RootLayout({ children }) {
  return (
    <html lang="en">
      <body style={{ margin: 0 }}>{children}</body>
    </html>
  );
}
