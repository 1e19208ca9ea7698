// Types of conecurl/vue (vue.js): the <Flipbook> component's props, events and exposed handle.
import type { DefineComponent } from 'vue';
import type { FlipbookEventMap } from './book/flipbook.js';
import type { FlipbookHandle, FlipbookOptionProps } from './components/framework-props.js';

export type { FlipbookHandle, FlipbookOptionProps, FlipbookState } from './components/framework-props.js';

export interface FlipbookProps extends FlipbookOptionProps {
  /** v-model:page: the page to show, updated as the book turns. */
  page?: number;
  /** The page to open at, without v-model. */
  defaultPage?: number;
}

/** Book events by their names (@turned, @pageerror, ...), and update:page for v-model:page. */
export type FlipbookEmits = { [K in keyof FlipbookEventMap]: (event: FlipbookEventMap[K]) => void } & {
  'update:page': (page: number) => void;
};

/**
 * The flipbook as a Vue 3 component; its default slot can hold the pages (an <img> an image page, any
 * other element a live HTML page). A template ref gives the FlipbookHandle. On a server it renders its
 * empty, sized box.
 */
export declare const Flipbook: DefineComponent<FlipbookProps, FlipbookHandle, {}, {}, {}, {}, {}, FlipbookEmits>;
export default Flipbook;
