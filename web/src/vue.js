// conecurl/vue: <Flipbook> for Vue 3. Props are the book's options and apply while it runs
// (book-mount.js), `v-model:page` follows the page shown, book events are emitted by their names, the
// default slot can hold the pages, and next/prev/flip/page/zoom are exposed. Nothing here needs a DOM
// until the component is mounted, so it renders on a server as a sized, empty box.
import { Teleport, defineComponent, getCurrentInstance, h, onBeforeUnmount, onMounted, onUpdated, ref } from 'vue';
import { BOOK_EVENTS } from './book/book-events.js';
import { BookMount } from './components/book-mount.js';
import { BOX_STYLE } from './components/book-box.js';
import { OPTION_PROPS, PAGE_PROPS, pageBoxes } from './components/framework-props.js';

// Pages from the default slot: an <img> is an image page ({ src, alt }); any other element is an HTML
// page, rendered by Vue into a box of its own (a Teleport) that the book lays over the page's place.
function pagesFromSlot(vnodes, boxes) {
  const pages = [];
  const teleports = [];
  const used = new Set();
  const elements = vnodes.flatMap((vnode) => (Array.isArray(vnode.children) && typeof vnode.type === 'symbol' ? vnode.children : [vnode]))
    .filter((vnode) => typeof vnode.type === 'string' || typeof vnode.type === 'object');
  elements.forEach((vnode, i) => {
    if (vnode.type === 'img') {
      const { src, alt } = vnode.props ?? {};
      pages.push(alt ? { src, alt } : src);
      return;
    }
    const key = vnode.key ?? i;
    const box = boxes.box(key);
    used.add(key);
    pages.push(box);
    teleports.push(h(Teleport, { to: box, key }, [vnode]));
  });
  boxes.keep(used);
  return { pages, teleports };
}

export const Flipbook = defineComponent({
  name: 'Flipbook',
  // Untyped on purpose: Vue casts an absent Boolean prop to false, and an absent option must mean its default.
  props: [...OPTION_PROPS, ...PAGE_PROPS],
  emits: [...BOOK_EVENTS, 'update:page'],
  setup(props, { emit, expose, slots }) {
    const listeners = getCurrentInstance().vnode.props ?? {};  // @error given? else errors go to the console
    const mount = new BookMount((type, event) => {
      emit(type, event);
      if (type === 'error' && !listeners.onError) console.error(event.detail.error);
    }, (page) => emit('update:page', page));
    expose(mount.handle);
    const container = ref(null);
    const mounted = ref(false);
    const boxes = pageBoxes();
    let current = {};
    let built = false;
    onMounted(() => { mounted.value = true; });
    onUpdated(() => {
      if (!built) {
        built = true;
        mount.mount(container.value, current);
      } else {
        mount.update(current);
      }
    });
    onBeforeUnmount(() => mount.unmount());
    return () => {
      const fromSlot = mounted.value && props.pages === undefined && props.pdf === undefined && props.document === undefined && slots.default;
      const { pages, teleports } = fromSlot ? pagesFromSlot(slots.default(), boxes) : { pages: props.pages, teleports: [] };
      current = { ...props, pages };
      // The box the book fills, as <cone-flipbook> sizes itself (book-box.js); a `style` attribute overrides any of it.
      return h('div', { ref: container, style: BOX_STYLE }, teleports);
    };
  },
});

export default Flipbook;
