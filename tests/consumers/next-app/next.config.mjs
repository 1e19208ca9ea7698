// The Next.js consumer (tests/browser/nextjs.spec.js): a production build of the app router with
// conecurl/react installed from the packed tarball.
export default {};
