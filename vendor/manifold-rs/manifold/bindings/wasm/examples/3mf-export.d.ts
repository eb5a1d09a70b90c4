declare module '@jscadui/3mf-export';
